//! The instruction-counting timer of the firmware benchmarks (`fw_bench`,
//! `fw_sweep`; shared with `#[path]`).
//!
//! Under QEMU with `-icount shift=0` virtual time advances one nanosecond per
//! executed instruction, so a timer clocked at `f` MHz ticks once per
//! `1000 / f` instructions. The timer is the board's (`build.rs` sets
//! `microraster_board` from `MICRORASTER_BOARD`):
//!
//! * `mps2-an386` (and any board but the micro:bit): SysTick on the core
//!   clock, 25 MHz on QEMU's mps2-an386, one tick per 40 instructions (its
//!   interrupt counts the 24-bit counter's wraps). Both
//!   instruction sets are timed there: the Cortex-M4 core runs Cortex-M0
//!   (`thumbv6m`) code unchanged, instruction for instruction.
//! * `microbit`: the nRF51's TIMER0 at 16 MHz, one tick per 62.5 instructions.
//!
//! [`calibrate`] checks the ratio with a loop of known length before anything
//! is measured.

use core::sync::atomic::{Ordering, compiler_fence};
use cortex_m_semihosting::hprintln;

/// Why the timer cannot be trusted.
pub enum ClockError {
    /// A timed region too long for the timer.
    Overflow,
    /// The timer does not tick once per [`PER_TICK`] instructions.
    Calibration,
}

impl core::fmt::Display for ClockError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ClockError::Overflow => write!(f, "a timed region is too long for {NAME}"),
            ClockError::Calibration => {
                write!(f, "the timer does not tick once per {}/{} instructions", PER_TICK.0, PER_TICK.1)
            }
        }
    }
}

/// Instructions in `ticks` ticks.
pub fn instructions(ticks: u64) -> u64 {
    ticks * PER_TICK.0 / PER_TICK.1
}

/// A timed region.
pub struct Span(u32);

impl Span {
    /// Starts timing.
    #[inline(always)]
    pub fn start() -> Span {
        compiler_fence(Ordering::SeqCst);
        let s = Span(begin());
        compiler_fence(Ordering::SeqCst);
        s
    }

    /// Ticks since [`Span::start`]; `None` if the timer cannot tell.
    #[inline(always)]
    pub fn stop(self) -> Option<u64> {
        compiler_fence(Ordering::SeqCst);
        let t = end(self.0);
        compiler_fence(Ordering::SeqCst);
        t
    }
}

/// Exactly `2 n` instructions (`n >= 1`): `subs` and `bne`, `n` times.
#[inline(always)]
fn spin(n: u32) {
    // SAFETY: register arithmetic and a local branch only.
    unsafe {
        core::arch::asm!(
            "2:",
            "subs {0}, #1",
            "bne 2b",
            inout(reg) n => _,
            options(nomem, nostack),
        );
    }
}

/// Starts the timer, times loops of known instruction counts and checks that
/// it ticks once per [`PER_TICK`] instructions (to 1 part in 10^4); prints
/// the measured ratio and the measurement's own overhead as a `#` note.
pub fn calibrate() -> Result<(), ClockError> {
    const N1: u32 = 100_000;
    const N2: u32 = 5_100_000;
    start();
    let time = |n: u32| {
        let t = Span::start();
        spin(n);
        t.stop()
    };
    let empty = {
        let t = Span::start();
        t.stop()
    };
    let (t1, t2, empty) = match (time(N1), time(N2), empty) {
        (Some(a), Some(b), Some(e)) => (a, b, e),
        _ => return Err(ClockError::Overflow),
    };
    // Instructions per tick, in thousandths.
    let ratio = 2_000 * u64::from(N2 - N1) / (t2 - t1).max(1);
    let (num, den) = PER_TICK;
    let nominal = 1_000 * num / den;
    hprintln!(
        "# timer: {}; {} instructions in {} ticks: {}.{:03} instructions per tick (nominal {}.{:03}); \
         an empty timed region reads {} ticks; resolution 1 tick",
        NAME,
        2 * u64::from(N2 - N1),
        t2 - t1,
        ratio / 1000,
        ratio % 1000,
        nominal / 1000,
        nominal % 1000,
        empty,
    );
    if ratio.abs_diff(nominal) * 10_000 > nominal {
        return Err(ClockError::Calibration);
    }
    Ok(())
}

// SysTick on the core clock (QEMU mps2-an386: 25 MHz, so one tick per 40
// instructions under `-icount shift=0`). It counts down from 2^24 − 1,
// restarted at the start of every region; its interrupt counts the wraps
// (every 671 million instructions), so a region may last 2^32 wraps. The
// handler's own few instructions per wrap are counted too (< 10^-7).
#[cfg(not(microraster_board = "microbit"))]
mod timer {
    use core::sync::atomic::{AtomicU32, Ordering};

    /// Instructions per tick, `(numerator, denominator)`.
    pub const PER_TICK: (u64, u64) = (40, 1);
    /// What counts.
    pub const NAME: &str = "SysTick, core clock (QEMU mps2-an386, 25 MHz), 24 bits + wrap count";
    const SYST_CSR: *mut u32 = 0xE000_E010 as *mut u32;
    const SYST_RVR: *mut u32 = 0xE000_E014 as *mut u32;
    const SYST_CVR: *mut u32 = 0xE000_E018 as *mut u32;
    const RELOAD: u32 = 0x00FF_FFFF;
    /// Wraps since the region began (written by the handler only while a
    /// region runs; thumbv6m has no atomic add, a single writer needs none).
    static WRAPS: AtomicU32 = AtomicU32::new(0);

    #[cortex_m_rt::exception]
    fn SysTick() {
        WRAPS.store(WRAPS.load(Ordering::Relaxed).wrapping_add(1), Ordering::Relaxed);
    }

    /// Starts the timer.
    pub fn start() {
        // SAFETY: SysTick registers.
        unsafe {
            SYST_CSR.write_volatile(0);
            SYST_RVR.write_volatile(RELOAD);
            SYST_CVR.write_volatile(0);
            SYST_CSR.write_volatile(0b111); // ENABLE, TICKINT, CLKSOURCE = core clock
            // The counter loads the reload value on its first tick.
            while SYST_CVR.read_volatile() == 0 {}
        }
    }

    #[inline(always)]
    pub fn begin() -> u32 {
        // SAFETY: SysTick registers. Writing CVR clears it (it reloads on
        // the next tick), so a region starts at a known count.
        unsafe {
            SYST_CVR.write_volatile(0);
            while SYST_CVR.read_volatile() == 0 {}
            WRAPS.store(0, Ordering::Relaxed);
            SYST_CVR.read_volatile()
        }
    }

    #[inline(always)]
    pub fn end(start: u32) -> Option<u64> {
        // SAFETY: SysTick registers. Read the wrap count around the counter
        // so that a wrap between the two reads is not missed.
        let (wraps, now) = loop {
            let w = WRAPS.load(Ordering::Relaxed);
            let now = unsafe { SYST_CVR.read_volatile() };
            if WRAPS.load(Ordering::Relaxed) == w {
                break (w, now);
            }
        };
        let ticks = u64::from(wraps) * (u64::from(RELOAD) + 1) + u64::from(start) - u64::from(now);
        Some(ticks)
    }
}

// The nRF51's TIMER0 (QEMU microbit) at 16 MHz, 32 bits: one tick per 62.5
// instructions, wraps after 268 · 10^9.
#[cfg(microraster_board = "microbit")]
mod timer {
    /// Instructions per tick, `(numerator, denominator)`.
    pub const PER_TICK: (u64, u64) = (125, 2);
    /// What counts.
    pub const NAME: &str = "nRF51 TIMER0 (QEMU microbit, 16 MHz), 32 bits";
    const TIMER0: usize = 0x4000_8000;

    fn reg(offset: usize) -> *mut u32 {
        (TIMER0 + offset) as *mut u32
    }

    /// Starts the timer.
    pub fn start() {
        // SAFETY: TIMER0 registers.
        unsafe {
            reg(0x004).write_volatile(1); // TASKS_STOP
            reg(0x504).write_volatile(0); // MODE: timer
            reg(0x508).write_volatile(3); // BITMODE: 32 bits
            reg(0x510).write_volatile(0); // PRESCALER: 16 MHz
            reg(0x00C).write_volatile(1); // TASKS_CLEAR
            reg(0x000).write_volatile(1); // TASKS_START
        }
    }

    #[inline(always)]
    fn now() -> u32 {
        // SAFETY: TIMER0 registers: capture into CC[0], read it.
        unsafe {
            reg(0x040).write_volatile(1); // TASKS_CAPTURE[0]
            reg(0x540).read_volatile() // CC[0]
        }
    }

    #[inline(always)]
    pub fn begin() -> u32 {
        now()
    }

    #[inline(always)]
    pub fn end(start: u32) -> Option<u64> {
        Some(u64::from(now().wrapping_sub(start)))
    }
}

pub use timer::{NAME, PER_TICK};
use timer::{begin, end, start};
