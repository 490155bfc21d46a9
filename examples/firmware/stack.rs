//! Stack high-water mark: the free RAM between the statics and the stack
//! pointer is painted with a pattern before the work and scanned afterwards;
//! the deepest word no longer holding the pattern marks the most stack ever
//! used. Shared by the firmware examples (`#[path]`).

const PAINT: u32 = 0x5AA5_C33C;

/// Bytes of stack room that must stay unused. A frame that comes closer to
/// the statics fails its firmware run: past them it would have overwritten
/// them silently (on the micro:bit, a corrupted semihosting `RefCell` showed
/// up as "already borrowed"), and a real application's interrupts need
/// room below the deepest frame too.
pub const MARGIN: usize = 512;

unsafe extern "C" {
    /// End of the statics (cortex-m-rt's linker script).
    static __sheap: u32;
    /// Top of the stack (cortex-m-rt's linker script).
    static _stack_start: u32;
}

fn bottom() -> usize {
    (&raw const __sheap) as usize
}

/// Paints the free stack below the current stack pointer (leaving 64 bytes
/// of margin for this function's own frame).
pub fn paint() {
    let sp = cortex_m::register::msp::read() as usize;
    let mut p = bottom();
    while p + 64 < sp {
        // SAFETY: word-aligned RAM between the statics and the stack
        // pointer, in use by nothing (no interrupts are enabled).
        unsafe { (p as *mut u32).write_volatile(PAINT) };
        p += 4;
    }
}

/// `(bytes of stack ever used since the last paint, bytes of room for the stack)`.
pub fn high_water() -> (usize, usize) {
    let top = (&raw const _stack_start) as usize;
    let mut p = bottom();
    // SAFETY: reads of RAM below the stack pointer.
    while p < top && unsafe { (p as *const u32).read_volatile() } == PAINT {
        p += 4;
    }
    (top - p, top - bottom())
}

/// `Err((used, room))` when `used` bytes of stack ([`high_water`]) come
/// within [`MARGIN`] bytes of the statics.
pub fn check((used, room): (usize, usize)) -> Result<(), (usize, usize)> {
    if used + MARGIN > room { Err((used, room)) } else { Ok(()) }
}
