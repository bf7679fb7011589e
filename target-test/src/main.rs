//! zerocal-core on the pendant's CPU: solves fixed test vectors in `f32` on a Cortex-M4F
//! (QEMU's netduinoplus2, an STM32F405) and prints the results over semihosting, for
//! `cargo xtask target-test` to compare with the `f64` solution of the same data.
//!
//! No embassy (its `init()` hangs under QEMU) and no board peripherals: only the core's
//! SysTick, which QEMU models.
//!
//! # Output, one line per fact (angles in degrees, `f32` printed round-trip exact)
//!
//! ```text
//! calibrate <instructions> <ticks>        known loop: SysTick ticks per instruction
//! case <name> stage0 <bx> <by>            stage-0 bias (only if the session has one)
//! case <name> stage1 <α> <β> <by> <Δθ2>   stage 1
//! case <name> fit <Δθ3> <Δθ4> <Δθ5> <Δθ6> stage 2
//! case <name> <stage> error <Variant> [<params>]   a stage's named refusal
//! measure <name> ticks <n> stack <bytes>  each case's solve: ticks, peak stack
//! done <cases>
//! ```
//!
//! The program exits with success after `done`; a panic or a fault prints a line and
//! exits with failure.

#![no_std]
#![no_main]

/// One session's readings, as the pendant would have taken them.
pub struct Case {
    /// One word: it starts every output line of the case.
    pub name: &'static str,
    /// The sensor's reading convention.
    pub convention: Convention,
    /// Stage 0.
    pub bias: BiasSource<f32>,
    /// Stage 1.
    pub stage1: AxisOneTurn<f32>,
    /// The paper robot's joint-2 direction (its arm: `Arm::paper_with_j2_direction`).
    pub j2_direction: i8,
    /// Stage 2.
    pub poses: &'static [PoseReading<f32>],
}

/// The generated test vectors (`cargo xtask target-test`, never committed): a static
/// `SESSIONS: [Case; N]`.
mod vectors {
    use crate::Case;
    use zerocal_core::model::{Convention, Tilt};
    use zerocal_core::session::BiasSource;
    use zerocal_core::stage0::BenchTurns;
    use zerocal_core::stage1::AxisOneTurn;
    use zerocal_core::stage2::PoseReading;

    include!(concat!(env!("OUT_DIR"), "/vectors.rs"));
}

use core::arch::asm;
use core::hint::black_box;
use core::panic::PanicInfo;
use core::ptr::addr_of;
use core::sync::atomic::{AtomicU32, Ordering};

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;
use cortex_m_rt::{entry, exception, ExceptionFrame};
use cortex_m_semihosting::{debug, hprintln};
use zerocal_core::bracket::Brackets;
use zerocal_core::error::Terse;
use zerocal_core::model::{Arm, Convention};
use zerocal_core::real::rad_to_deg;
use zerocal_core::session::{
    self, BiasSource, SessionError, SessionOutcome, SessionReadings, StageTemperatures,
};
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::{FitConfig, PoseReading};

/// SysTick reload: the full 24 bits, so it wraps every 2^24 ticks.
const SYSTICK_RELOAD: u32 = 0x00FF_FFFF;

/// SysTick wraps so far, counted by the SysTick exception.
static SYSTICK_WRAPS: AtomicU32 = AtomicU32::new(0);

/// Iterations of the two-instruction calibration loop.
const CALIBRATION_ITERATIONS: u32 = 500_000;

/// Stack painting leaves this much below the measuring function's stack pointer alone:
/// the painting function's own frame lives there.
const PAINT_GUARD_BYTES: usize = 1024;

/// The word the free stack is painted with before the measured fit.
const STACK_PAINT: u32 = 0xA5C3_5A3C;

extern "C" {
    /// Lowest address the stack may grow down to (end of the statics), from
    /// cortex-m-rt's `link.x`.
    static _stack_end: u32;
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        fail("core peripherals already taken")
    };
    start_systick(&mut peripherals.SYST);

    let before = ticks();
    calibration_loop(black_box(CALIBRATION_ITERATIONS));
    let after = ticks();
    hprintln!(
        "calibrate {} {}",
        2 * u64::from(CALIBRATION_ITERATIONS),
        after - before
    );

    for case in vectors::SESSIONS.iter() {
        run(case);
    }
    hprintln!("done {}", vectors::SESSIONS.len());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

/// Solves one session with core's session solver, as the pendant does, and prints its
/// lines.
fn run(case: &Case) {
    let name = case.name;
    let readings = SessionReadings {
        convention: case.convention,
        arm: Arm::paper_with_j2_direction(case.j2_direction),
        masses: None,
        brackets: &Brackets::default(),
        bias: case.bias,
        stage1: case.stage1,
        poses: case.poses,
        // The vectors carry one capture a pose: nothing to pair.
        capture_index: None,
        temperatures: StageTemperatures::default(),
        closing: None,
    };
    let config = FitConfig::default();
    // Every case is measured: the stack budget holds the deepest, refusals included.
    let outcome = measured_solve(name, &readings, &config);
    if let Some(b) = &outcome.bias {
        hprintln!(
            "case {} stage0 {:?} {:?}",
            name,
            rad_to_deg(b.x_rad),
            rad_to_deg(b.y_rad)
        );
    }
    if let Some(s1) = &outcome.stage1 {
        hprintln!(
            "case {} stage1 {:?} {:?} {:?} {:?}",
            name,
            rad_to_deg(s1.base_tilt.alpha_rad),
            rad_to_deg(s1.base_tilt.beta_rad),
            rad_to_deg(s1.bias_y_rad),
            rad_to_deg(s1.delta_theta2_rad)
        );
    }
    match outcome.result {
        Ok(r) => {
            let [d3, d4, d5, d6] = r.fit.offsets_rad.map(rad_to_deg);
            hprintln!("case {} fit {:?} {:?} {:?} {:?}", name, d3, d4, d5, d6);
        }
        Err(SessionError::Stage0(e)) => hprintln!("case {} stage0 error {}", name, Terse(&e)),
        Err(SessionError::Closing(e)) => hprintln!("case {} closing error {}", name, Terse(&e)),
        Err(SessionError::Stage1(e)) => hprintln!("case {} stage1 error {}", name, Terse(&e)),
        Err(SessionError::Stage2(e)) => hprintln!("case {} fit error {}", name, Terse(&e)),
        Err(SessionError::Warmed { .. }) => hprintln!("case {} session error Warmed", name),
    }
}

/// The session solve, timed with SysTick and with its peak stack measured by painting,
/// printed as a `measure` line.
///
/// Stack: every word between the end of the statics and [`PAINT_GUARD_BYTES`] below
/// this function's stack pointer is set to [`STACK_PAINT`]; afterwards, the lowest
/// word no longer holding it marks the deepest the solve's stack reached. The figure is
/// from this function's stack pointer down, so it covers `solve`'s frame and all it calls.
#[inline(never)]
fn measured_solve(
    name: &str,
    readings: &SessionReadings<'_, f32>,
    config: &FitConfig<f32>,
) -> SessionOutcome<f32> {
    let sp = cortex_m::register::msp::read() as usize;
    let bottom = addr_of!(_stack_end) as usize;
    let top = sp - PAINT_GUARD_BYTES;
    // SAFETY: [bottom, top) is the unused part of the stack region: below every live
    // frame (the painting function's own frame lies in the guard above `top`) and
    // above the statics. No interrupt handler runs on it meanwhile except SysTick's,
    // whose frame would only make the figure larger.
    unsafe { paint(bottom, top) };
    let start = ticks();
    let outcome = solve(black_box(readings), black_box(config));
    let end = ticks();
    // SAFETY: as for `paint`: the range is the stack region below the live frames.
    let lowest = unsafe { lowest_touched(bottom, top) };
    hprintln!(
        "measure {} ticks {} stack {}",
        name,
        end - start,
        sp - lowest
    );
    outcome
}

/// The solve on its own frame, so the stack it takes is below the measuring function's.
#[inline(never)]
fn solve(readings: &SessionReadings<'_, f32>, config: &FitConfig<f32>) -> SessionOutcome<f32> {
    session::solve(readings, config)
}

/// Fills the words in `[bottom, top)` with [`STACK_PAINT`].
///
/// # Safety
/// The range must be writable memory that nothing live uses.
#[inline(never)]
unsafe fn paint(bottom: usize, top: usize) {
    let mut address = bottom;
    while address + 4 <= top {
        // SAFETY: by the caller's contract.
        unsafe { (address as *mut u32).write_volatile(STACK_PAINT) };
        address += 4;
    }
}

/// The lowest address in `[bottom, top)` whose word no longer holds [`STACK_PAINT`], or
/// `top` when none was touched.
///
/// # Safety
/// The range must be readable memory.
#[inline(never)]
unsafe fn lowest_touched(bottom: usize, top: usize) -> usize {
    let mut address = bottom;
    while address + 4 <= top {
        // SAFETY: by the caller's contract.
        if unsafe { (address as *const u32).read_volatile() } != STACK_PAINT {
            return address;
        }
        address += 4;
    }
    top
}

/// Runs SysTick from the processor clock, wrapping every 2^24 ticks (counted by the
/// SysTick exception).
///
/// Under QEMU with `-icount shift=0` virtual time advances exactly 1 ns per executed
/// instruction, and SysTick's processor clock is the machine's SYSCLK (168 MHz on the
/// netduinoplus2), so one tick is 1000/168 ≈ 5.95 instructions whatever the host's
/// speed. The exact ratio is not assumed: [`calibration_loop`] measures it, and the
/// xtask converts ticks to instructions with it.
fn start_systick(syst: &mut SYST) {
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(SYSTICK_RELOAD);
    syst.clear_current();
    syst.enable_interrupt();
    syst.enable_counter();
}

/// SysTick ticks since [`start_systick`]. Reads the wrap count on both sides of the
/// counter and retries if a wrap came in between.
///
/// The counter starts at 0 (cleared), reloads to [`SYSTICK_RELOAD`] on the next tick and
/// counts down; the exception (one wrap) comes as it reaches 0 again. Counting the
/// value 0 as the end of a wrap, `(RELOAD + 1 − current) mod (RELOAD + 1)` ticks have
/// passed in the current wrap: 0 at the start, continuous across wraps.
fn ticks() -> u64 {
    let per_wrap = u64::from(SYSTICK_RELOAD) + 1;
    loop {
        let wraps = SYSTICK_WRAPS.load(Ordering::SeqCst);
        let current = u64::from(SYST::get_current());
        if SYSTICK_WRAPS.load(Ordering::SeqCst) == wraps {
            return u64::from(wraps) * per_wrap + (per_wrap - current) % per_wrap;
        }
    }
}

/// Exactly `2 × iterations` instructions (`subs` and `bne` per iteration), plus the
/// call: the known work against which SysTick ticks are converted to instructions.
#[inline(never)]
fn calibration_loop(iterations: u32) {
    if iterations == 0 {
        return;
    }
    // SAFETY: register-only arithmetic and a local branch.
    unsafe {
        asm!(
            "2:",
            "subs {n}, {n}, #1",
            "bne 2b",
            n = inout(reg) iterations => _,
            options(nomem, nostack),
        );
    }
}

#[exception]
fn SysTick() {
    SYSTICK_WRAPS.fetch_add(1, Ordering::SeqCst);
}

#[exception]
unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
    hprintln!("hardfault at pc {:#010x}", frame.pc());
    exit_failure()
}

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    hprintln!("panic: {}", info);
    exit_failure()
}

/// Prints `reason` and exits with failure.
fn fail(reason: &str) -> ! {
    hprintln!("failure: {}", reason);
    exit_failure()
}

/// Ends the QEMU run with a failure status.
fn exit_failure() -> ! {
    debug::exit(debug::EXIT_FAILURE);
    // Without a semihosting host the call returns: stop here, the xtask's time limit
    // reports the hang.
    loop {
        cortex_m::asm::wfi();
    }
}
