//! The band fills and the view's clear.

use super::{Band, clear_run, fill_run};
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};

/// Both fills write `v` to exactly the slice they get, for every
/// length around their block sizes and every start (the slice inside a
/// larger buffer whose other values must stay).
#[test]
fn fills_write_exactly_their_slice() {
    type Fill = fn(&mut [u16], u16);
    let fills: [(&str, Fill); 2] = [("fill_run", fill_run), ("clear_run", clear_run)];
    for (name, fill) in fills {
        for start in 0..3 {
            for len in 0..70 {
                let mut buf = [0x5A5Au16; 80];
                fill(&mut buf[start..start + len], 0xFFFF);
                for (i, &p) in buf.iter().enumerate() {
                    let inside = (start..start + len).contains(&i);
                    assert_eq!(
                        p,
                        if inside { 0xFFFF } else { 0x5A5A },
                        "{name}: start {start}, len {len}, index {i}"
                    );
                }
            }
        }
    }
}

/// The embedded-graphics `clear` of a view writes every pixel of the
/// view's rows and nothing of the band's other rows.
#[test]
fn view_clear_writes_exactly_its_rows() {
    for rows in 0..=5 {
        let mut band = Band::<Rgb565, 13, 5>::new(Rgb565::RED);
        let Ok(()) = band.view_uncleared(40, rows).clear(Rgb565::BLACK);
        for (i, row) in band.rows().iter().enumerate() {
            let want = if i < rows { Rgb565::BLACK } else { Rgb565::RED };
            assert!(row.iter().all(|&p| p == want), "{rows} rows: row {i}");
        }
    }
}
