// error: Scalar
// The vertex stage runs on f32 or Fx only.
use microraster::math::Mat4;
use microraster::pipeline::Pipeline;

fn main() {
    let _ = Pipeline::<f64, 4>::new(Mat4::IDENTITY, Mat4::IDENTITY, 1.0, 32, 32);
}
