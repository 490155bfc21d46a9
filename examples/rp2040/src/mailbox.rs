//! Where the emulator build (`--features emu`) and the host tool that runs
//! it (examples/rp2040/emu) meet: 32-bit words in SRAM4, the 4 KB scratch
//! bank at `0x2004_0000` that memory.x leaves out of RAM (nothing else
//! uses it). Included by path by both programs, so the two agree.
//!
//! The host writes [`CONFIG`] (with [`MAGIC`]) before the firmware starts;
//! the firmware writes the rest. Each frame's band records go to slot
//! `frame % SLOTS`: per band `y0 rows crc count` (four words), then the
//! frame's `rows crc count`; [`FRAMES`] counts the finished frames and is
//! written last, after the slot.

/// Address of word 0.
pub const BASE: u32 = 0x2004_0000;
/// Word 0: [`MAGIC`] when the host has written the configuration.
pub const CONFIG: usize = 0;
/// The value of word [`CONFIG`] that makes word [`CORES`] count.
pub const MAGIC: u32 = 0x4D52_4346;
/// Word 1: the cores that render (1: core 0 alone, 2: both).
pub const CORES: usize = 1;
/// Word 2: frames finished (their last band sent).
pub const FRAMES: usize = 2;
/// Words 3 and 4: what core 0 and core 1 are doing ([`VERTEX`], [`RENDER`],
/// [`WAIT`], [`SEND`]; 0 before they start).
pub const STATE: usize = 3;
/// Word 5: [`PANICKED`] once the firmware has panicked.
pub const PANIC: usize = 5;
/// The value of word [`PANIC`] after a panic.
pub const PANICKED: u32 = 0xDEAD_DEAD;
/// A core's state: rasterising its bands (and clearing the others).
pub const RENDER: u32 = 1;
/// A core's state: its band is finished, waiting for its turn at the panel.
pub const WAIT: u32 = 2;
/// A core's state: sending its band (SPI) and folding it into the CRCs.
pub const SEND: u32 = 3;
/// A core's state: the vertex stage (each core runs it for the whole frame).
pub const VERTEX: u32 = 4;
/// Word where slot 0 starts.
pub const SLOT0: usize = 16;
/// Words of a slot: four per band, three for the frame.
pub const SLOT_WORDS: usize = 64;
/// Slots (frames kept).
pub const SLOTS: usize = 4;
