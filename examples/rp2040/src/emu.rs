//! The emulator build (`--features emu`, see Cargo.toml): the firmware
//! reports to the host through the [`mailbox`](crate::mailbox) instead of
//! only to the panel. It reads how many cores render, marks what each core
//! is doing, folds every band sent into a CRC-32 (the host's firmware
//! scheme: `Rgb565` little-endian, examples/firmware/workload/crc.rs) and
//! publishes the band and frame records. It also switches SPI0 to loopback,
//! without which the emulator's SPI returns no words and
//! `SpiBus::write` waits forever (the panel gets nothing either way).

use core::cell::Cell;
use core::ptr::{read_volatile, write_volatile};
use core::sync::atomic::{Ordering, compiler_fence};

use critical_section::{CriticalSection, Mutex};
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use embedded_graphics_core::primitives::Rectangle;
use rp2040_hal::pac;

use crate::crc::Crc32;
use crate::mailbox::*;
use crate::scene::BANDS;

/// The frame's CRC so far, over the bands sent in order (by either core).
static FRAME: Mutex<Cell<(Crc32, u32, u32)>> = Mutex::new(Cell::new((Crc32::new(), 0, 0)));

fn word(i: usize) -> *mut u32 {
    (BASE as usize + 4 * i) as *mut u32
}

fn write(i: usize, value: u32) {
    // SAFETY: SRAM4 (0x2004_0000..0x2004_1000) is outside the linker's
    // RAM (memory.x), so no Rust object lives there; the mailbox has 272
    // words, all below 0x2004_1000; volatile, so each write reaches the
    // memory the host reads.
    unsafe { write_volatile(word(i), value) }
}

fn read(i: usize) -> u32 {
    // SAFETY: as in `write`.
    unsafe { read_volatile(word(i)) }
}

/// The cores the host asked for (2 unless it wrote 1).
pub fn cores() -> usize {
    if read(CONFIG) == MAGIC && read(CORES) == 1 { 1 } else { 2 }
}

/// Core `core` now does `state` ([`VERTEX`], [`RENDER`], [`WAIT`], [`SEND`]).
pub fn state(core: usize, state: u32) {
    compiler_fence(Ordering::SeqCst);
    write(STATE + core, state);
    compiler_fence(Ordering::SeqCst);
}

/// Band `index` of frame `frame` was sent: its record, and after the
/// frame's last band the frame's record and the frame count. Called in
/// band order (the panel's turn), inside the panel's critical section.
pub fn band(cs: CriticalSection<'_>, frame: usize, index: usize, area: Rectangle, pixels: &[Rgb565]) {
    let (mut total, mut rows, mut count) = FRAME.borrow(cs).get();
    let mut crc = Crc32::new();
    for px in pixels {
        let bytes = px.into_storage().to_le_bytes();
        crc.update(&bytes);
        total.update(&bytes);
    }
    rows += area.size.height;
    count += pixels.len() as u32;
    let slot = SLOT0 + (frame % SLOTS) * SLOT_WORDS;
    let at = slot + 4 * index;
    write(at, area.top_left.y as u32);
    write(at + 1, area.size.height);
    write(at + 2, crc.value());
    write(at + 3, pixels.len() as u32);
    if index + 1 < BANDS {
        FRAME.borrow(cs).set((total, rows, count));
        return;
    }
    let at = slot + 4 * BANDS;
    write(at, rows);
    write(at + 1, total.value());
    write(at + 2, count);
    FRAME.borrow(cs).set((Crc32::new(), 0, 0));
    compiler_fence(Ordering::SeqCst);
    write(FRAMES, frame as u32 + 1);
}

/// The panic marker.
pub fn panicked() {
    write(PANIC, PANICKED);
}

/// SPI0 in loopback (SSPCR1.LBM): every word sent comes back, as the
/// emulator's SPI needs (see the module docs).
pub fn loopback() {
    // SAFETY: one read-modify-write of SPI0's SSPCR1 on core 0 before core
    // 1 starts; the HAL's `Spi` owns SPI0 but keeps no copy of SSPCR1.
    let spi = unsafe { &*pac::SPI0::ptr() };
    spi.sspcr1().modify(|_, w| w.lbm().set_bit());
}
