//! Depth comparisons against their definitions, and the band that applies
//! them: `test_and_set`, clearing, row access and `NoDepth`.

use super::*;
use core::cmp::Ordering;

const ALL_TESTS: [DepthTest; 8] = [
    DepthTest::Less,
    DepthTest::LessEqual,
    DepthTest::Greater,
    DepthTest::GreaterEqual,
    DepthTest::Equal,
    DepthTest::NotEqual,
    DepthTest::Always,
    DepthTest::Never,
];

/// The definition of each test, from `Ordering`.
fn defined(t: DepthTest, new: u32, stored: u32) -> bool {
    let o = new.cmp(&stored);
    match t {
        DepthTest::Less => o == Ordering::Less,
        DepthTest::LessEqual => o != Ordering::Greater,
        DepthTest::Greater => o == Ordering::Greater,
        DepthTest::GreaterEqual => o != Ordering::Less,
        DepthTest::Equal => o == Ordering::Equal,
        DepthTest::NotEqual => o != Ordering::Equal,
        DepthTest::Always => true,
        DepthTest::Never => false,
    }
}

const GRID: [u32; 9] = [0, 1, 2, 3, 254, 255, 256, u32::MAX - 1, u32::MAX];

#[test]
fn depth_tests_match_definitions() {
    const _: () = assert!(DepthTest::Less.passes(1, 2) && !DepthTest::Never.passes(0, 1));
    let mut n = 0;
    for t in ALL_TESTS {
        for new in GRID {
            for stored in GRID {
                assert_eq!(t.passes(new, stored), defined(t, new, stored), "{t:?} {new} {stored}");
                n += 1;
            }
        }
    }
    assert_eq!(DepthState::default(), DepthState::LESS_WRITE);
    assert_eq!(DepthTest::default(), DepthTest::Less);
    println!("depth tests: {n} (test, new, stored) combinations match their definitions");
}

#[test]
fn test_and_set_applies_test_and_write_mask() {
    let mut n = 0;
    for t in ALL_TESTS {
        for write in [false, true] {
            let state = DepthState::new(t, write);
            for stored in [0, 1, 2, 3, 0xFFFE, 0xFFFF] {
                for new in [0, 1, 2, 3, 0xFFFE, 0xFFFF, 0x1_0000, u32::MAX] {
                    let mut z = DepthBand::<Depth16, 4, 2>::new();
                    z.clear_to(2, stored);
                    let want = t.passes(new.min(0xFFFF), stored);
                    assert_eq!(z.test_and_set(1, 3, new, state), want, "{state:?} {new} {stored}");
                    let after = if want && write { new.min(0xFFFF) } else { stored };
                    assert_eq!(z.get(1, 3), Some(after));
                    // No other value changed.
                    let others = z.rows().iter().flatten().filter(|&&v| v == stored as u16).count();
                    assert_eq!(others, if after == stored { 8 } else { 7 });
                    n += 1;
                }
            }
        }
    }
    println!("test_and_set: {n} (test, write, stored, new) cases respect the test and write mask");
    // Outside the band: false, nothing written, no panic.
    let mut z = DepthBand::<Depth8, 4, 2>::new();
    for (row, x) in [(2, 0), (0, 4), (usize::MAX, usize::MAX)] {
        assert!(!z.test_and_set(row, x, 0, DepthState::ALWAYS_WRITE));
    }
    assert!(z.rows().iter().flatten().all(|&v| v == 255));
    assert!(z.test_and_set(0, 0, 1000, DepthState::ALWAYS_WRITE)); // clamps to 255
    assert_eq!(z.get(0, 0), Some(255));
    let mut z = DepthBand::<Depth24, 1, 1>::new();
    assert!(z.test_and_set(0, 0, u32::MAX, DepthState::ALWAYS_WRITE));
    assert_eq!(z.get(0, 0), Some(0xFF_FFFF));
}

#[test]
fn clear_row_access_and_const_construction() {
    static Z: DepthBand<Depth32, 3, 2> = DepthBand::new();
    assert!(Z.rows().iter().flatten().all(|&v| v == u32::MAX));
    let mut z = DepthBand::<Depth16, 3, 3>::default();
    for r in 0..3 {
        z.row_mut(r).unwrap().fill(5);
    }
    assert!(z.row_mut(3).is_none() && z.row(3).is_none() && z.get(0, 3).is_none());
    z.clear(2); // only the first two rows
    assert_eq!((z.row(1), z.row(2)), (Some(&[0xFFFF; 3]), Some(&[5; 3])));
    z.clear(usize::MAX); // clamps to H
    assert!(z.rows().iter().flatten().all(|&v| v == 0xFFFF));
    z.clear_to(3, 0);
    assert!(z.rows().iter().flatten().all(|&v| v == 0));
}

#[test]
fn no_depth_is_free_and_always_passes() {
    let mut z = DepthBand::<NoDepth, 320, 16>::new();
    assert_eq!(size_of::<DepthBand<NoDepth, 320, 16>>(), 0);
    let mut n = 0;
    for t in ALL_TESTS {
        for write in [false, true] {
            for (row, x, d) in [(0, 0, 0), (15, 319, u32::MAX), (16, 320, 7), (usize::MAX, 0, 1)] {
                assert!(z.test_and_set(row, x, d, DepthState::new(t, write)));
                n += 1;
            }
        }
    }
    z.clear(16);
    z.clear_to(16, 3);
    assert_eq!((z.get(15, 319), z.get(16, 0)), (Some(0), None));
    let () = quantize_unit::<NoDepth>(UNIT_ONE);
    println!("NoDepth: 0 bytes, {n} calls all passed");
}
