//! What stops the pendant and how it comes back: a panic resets it in release builds
//! (after keeping where it happened for the next boot's screen), the independent
//! watchdog resets it if the executor stops running; debug builds keep panic-probe's
//! halt for the debugger.
//!
//! The release build made by `cargo xtask firmware` with the build-std toolchain aborts
//! on panic at once (`-Cpanic=immediate-abort`: no panic messages or locations in
//! flash: about 22 KB less than a stable-toolchain build, `cargo xtask size`). The abort is a HardFault, whose
//! handler keeps the faulting address instead (`arm-none-eabi-addr2line -e
//! zerocal-firmware ADDR` names the line). A stable-toolchain build keeps the panic handler below, which
//! keeps the file and line.

#[cfg(not(debug_assertions))]
use core::fmt::Write as _;
use core::mem::MaybeUninit;

use embassy_stm32::wdg::IndependentWatchdog;
use embassy_time::Timer;
use zerocal_pendant::screen::{RestartCause, RestartNote};

use crate::board::WATCHDOG_TIMEOUT_US;

/// A panic's message across the reset: in `.uninit` RAM, which cortex-m-rt neither
/// zeroes nor initialises.
#[repr(C)]
struct PanicNote {
    magic: u32,
    len: u32,
    bytes: [u8; 64],
}

/// "ZCPN": the note is valid.
const MAGIC: u32 = 0x5A43_504E;

#[link_section = ".uninit.zerocal_panic_note"]
static mut PANIC_NOTE: MaybeUninit<PanicNote> = MaybeUninit::uninit();

/// The note the last reset left, if any: a panic's message, or the watchdog's flag in
/// RCC_CSR (then cleared, with every other reset flag).
pub fn take_restart_note() -> Option<RestartNote> {
    // SAFETY: read once at start-up, before anything can panic again; the bytes are
    // plain data, any value is valid.
    let note = unsafe { (*core::ptr::addr_of!(PANIC_NOTE)).assume_init_read() };
    // SAFETY: as above; the magic is cleared so the note shows once.
    unsafe {
        (*core::ptr::addr_of_mut!(PANIC_NOTE))
            .assume_init_mut()
            .magic = 0
    };
    let rcc = embassy_stm32::pac::RCC;
    // WDGRSTF: the independent watchdog (IWDGRSTF in RM0383).
    let watchdog = rcc.csr().read().wdgrstf();
    rcc.csr().modify(|w| w.set_rmvf(true));
    if note.magic == MAGIC {
        let len = (note.len as usize).min(note.bytes.len());
        let mut message = heapless::String::new();
        let text = core::str::from_utf8(&note.bytes[..len]).unwrap_or("(unreadable)");
        let _ = message.push_str(text);
        return Some(RestartNote {
            cause: RestartCause::Panic,
            message,
        });
    }
    watchdog.then(|| RestartNote {
        cause: RestartCause::Watchdog,
        message: heapless::String::new(),
    })
}

/// Pets the watchdog at a quarter of its nominal timeout, forever. It runs on the same
/// executor as everything else: a task that never yields starves it, and the reset
/// follows.
#[embassy_executor::task]
pub async fn watchdog_task(
    mut watchdog: IndependentWatchdog<'static, embassy_stm32::peripherals::IWDG>,
) -> ! {
    watchdog.unleash();
    loop {
        watchdog.pet();
        Timer::after_micros(u64::from(WATCHDOG_TIMEOUT_US / 4)).await;
    }
}

/// Writes into the note's buffer, cutting what does not fit.
#[cfg(not(debug_assertions))]
struct NoteWriter<'a> {
    bytes: &'a mut [u8; 64],
    len: usize,
}

#[cfg(not(debug_assertions))]
impl core::fmt::Write for NoteWriter<'_> {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        for &b in s.as_bytes() {
            if let Some(slot) = self.bytes.get_mut(self.len) {
                *slot = b;
                self.len += 1;
            }
        }
        Ok(())
    }
}

/// Release builds: keep the message, reset. A pendant in the field must come back,
/// and the next boot shows what happened.
#[cfg(not(debug_assertions))]
#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    cortex_m::interrupt::disable();
    // SAFETY: interrupts are off and this never returns: nothing else touches the note.
    let note = unsafe { &mut *core::ptr::addr_of_mut!(PANIC_NOTE) };
    let note = note.write(PanicNote {
        magic: 0,
        len: 0,
        bytes: [0; 64],
    });
    let mut writer = NoteWriter {
        bytes: &mut note.bytes,
        len: 0,
    };
    // The place only: formatting the message would link every panic site's argument
    // formatting (floats included, ~6 KiB) into a 128 KiB budget; file and line name
    // the check that failed.
    if let Some(location) = info.location() {
        let _ = writer.write_str(location.file());
        let _ = writer.write_str(":");
        let mut digits = [0u8; 10];
        let mut n = location.line();
        let mut i = digits.len();
        loop {
            i -= 1;
            digits[i] = b'0' + (n % 10) as u8;
            n /= 10;
            if n == 0 || i == 0 {
                break;
            }
        }
        if let Ok(text) = core::str::from_utf8(&digits[i..]) {
            let _ = writer.write_str(text);
        }
    }
    note.len = writer.len as u32;
    note.magic = MAGIC;
    cortex_m::peripheral::SCB::sys_reset()
}

/// Release builds: a HardFault (an immediate-abort panic, or a fault) keeps the
/// faulting instruction's address in the note and resets.
#[cfg(not(debug_assertions))]
#[cortex_m_rt::exception]
unsafe fn HardFault(frame: &cortex_m_rt::ExceptionFrame) -> ! {
    cortex_m::interrupt::disable();
    // SAFETY: interrupts are off and this never returns: nothing else touches the note.
    let note = unsafe { &mut *core::ptr::addr_of_mut!(PANIC_NOTE) };
    let note = note.write(PanicNote {
        magic: 0,
        len: 0,
        bytes: [0; 64],
    });
    let mut writer = NoteWriter {
        bytes: &mut note.bytes,
        len: 0,
    };
    let _ = writer.write_str("fault at 0x");
    let pc = frame.pc();
    let mut hex = [0u8; 8];
    for (i, h) in hex.iter_mut().enumerate() {
        let nibble = (pc >> (28 - 4 * i)) & 0xF;
        *h = b"0123456789abcdef"[nibble as usize];
    }
    if let Ok(text) = core::str::from_utf8(&hex) {
        let _ = writer.write_str(text);
    }
    note.len = writer.len as u32;
    note.magic = MAGIC;
    cortex_m::peripheral::SCB::sys_reset()
}

#[cfg(debug_assertions)]
use panic_probe as _;
