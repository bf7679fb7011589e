//! zerocal-pendant-desktop: the pendant's application (`zerocal-pendant`) on the
//! desktop. The same tasks as on the board, on a simulated clock ([`exec`]), with a
//! simulated SCL3300 at the SPI-frame level on a simulated robot ([`world`], [`io`]),
//! the SSD1306 as a frame buffer ([`panel`]), the USB port as byte pipes ([`io`]) and
//! the F411's flash sectors (`zerocal_sim::flash`). [`operator`] presses the buttons
//! and moves the robot as the screens ask.
//!
//! Whole runs, for `cargo xtask pendant-sim` and the tests: a calibration
//! [`session`], the [`power_cuts`] campaign, the [`faults`] scenarios, a [`bracket`]'s
//! calibration, a link
//! [`conversation`] and the screen [`gallery`]. [`script`] drives a session step by
//! step for tests that look at the pendant between stages; [`port`] makes the pendant
//! a serial port that a desktop program (`zerocal pendant`) drives in step with its
//! clock.

pub mod agreement;
pub mod bracket;
pub mod conversation;
pub mod exec;
pub mod faults;
pub mod gallery;
pub mod io;
pub mod operator;
pub mod panel;
pub mod port;
pub mod power_cuts;
pub mod script;
pub mod session;
pub mod world;

use std::cell::RefCell;
use std::future::Future;
use std::rc::Rc;

use embassy_futures::join::join5;
use embassy_futures::select::{select, Either};
use embassy_time::Instant;
use zerocal_core::plan::{Candidate, DEFAULT_POOL};
use zerocal_procedure::{pendant_default, PendantUnit, UnitId};

use exec::Stop;
use io::{ButtonLevels, HostButtons, HostLink, HostSpi, PendantRx, PendantTx};
use panel::{HostPanel, PanelLog};
use world::{World, WorldConfig};
use zerocal_pendant::channels::Shared;
use zerocal_pendant::config::procedure_config;
use zerocal_pendant::procedure::Boot;
use zerocal_pendant::screen::RestartNote;
use zerocal_sim::flash::{SimFlash, STORE_RANGE};

/// The pendant's default plan, as the firmware's build computes it: core's planner on
/// the pendant's configuration.
///
/// # Errors
/// The planner's refusal, as text.
pub fn default_plan() -> Result<Vec<[f32; 6]>, String> {
    let config = procedure_config();
    let mut pool = vec![Candidate::<f32>::default(); DEFAULT_POOL];
    pendant_default(&config, &mut pool)
        .map(|plan| plan.to_vec())
        .map_err(|e| format!("core's planner refused the default plan: {e:?}"))
}

/// The desktop pendant's unit: a fixed fake ID (the bytes of `desktop-sim!`; a real
/// unit's is its chip's) and this crate's version as the firmware's.
pub const DESKTOP_UNIT: PendantUnit = PendantUnit {
    id: UnitId(*b"desktop-sim!"),
    firmware: env!("CARGO_PKG_VERSION"),
};

/// Everything around the pendant that outlives a power cut: the world, the flash, the
/// display's log, the buttons, the cable.
pub struct Rig {
    /// The robot, the pendant's place and the SCL3300.
    pub world: Rc<RefCell<World>>,
    /// The flash chip.
    pub flash: SimFlash,
    /// What the display showed.
    pub panel: Rc<RefCell<PanelLog>>,
    /// The buttons' levels.
    pub buttons: Rc<ButtonLevels>,
    /// The USB cable and its bytes.
    pub link: HostLink,
    /// The plan the pendant starts with, and the robot program's poses.
    pub plan: Vec<[f32; 6]>,
    /// In a check, the check program's poses: indices into `plan` (core's
    /// `check_poses`, as `zerocal program --check` writes them).
    pub check: RefCell<Option<Vec<usize>>>,
    /// The note the board hands the next boot (a panic's message).
    pub restart: RefCell<Option<RestartNote>>,
}

impl Rig {
    /// A rig with an erased flash, whose power cuts stop the simulated clock's run.
    ///
    /// # Errors
    /// The planner's refusal of the default plan.
    pub fn new(world: WorldConfig, flash_seed: u64) -> Result<Rig, String> {
        let flash = SimFlash::new(flash_seed);
        flash.on_power_cut(exec::cut_power);
        Ok(Rig {
            world: Rc::new(RefCell::new(World::new(world))),
            flash,
            panel: Rc::new(RefCell::new(PanelLog::default())),
            buttons: Rc::new(ButtonLevels::default()),
            link: HostLink::default(),
            plan: default_plan()?,
            check: RefCell::new(None),
            restart: RefCell::new(None),
        })
    }

    /// The pendant's tasks, as the firmware spawns them.
    async fn pendant(&self, shared: &Shared) -> ! {
        let restart = self.restart.borrow_mut().take();
        let (never, ..) = join5(
            zerocal_pendant::procedure::run(
                shared,
                Boot {
                    flash: self.flash.clone(),
                    store_range: STORE_RANGE,
                    default_plan: &self.plan,
                    restart,
                    pendant: Some(DESKTOP_UNIT),
                },
            ),
            zerocal_pendant::sensor::run(shared, HostSpi::new(self.world.clone())),
            zerocal_pendant::buttons::run(shared, HostButtons::new(self.buttons.clone())),
            zerocal_pendant::ui::run(shared, HostPanel::new(self.panel.clone())),
            self.usb(shared),
        )
        .await;
        never
    }

    /// The board's USB loop: serve while plugged, wait for the cable otherwise.
    async fn usb(&self, shared: &Shared) -> ! {
        loop {
            if self.link.plugged.get() {
                let _ = zerocal_pendant::link::serve(
                    shared,
                    &mut PendantRx(&self.link),
                    &mut PendantTx(&self.link),
                )
                .await;
            }
            if !self.link.plugged.get() {
                self.link.cable.wait().await;
            }
        }
    }

    /// Powers the pendant up and runs `script` beside it until the script finishes,
    /// the power is cut or the simulated clock reaches `deadline`. What the display
    /// shows goes dark first; the world, the flash and the cable stay as they are.
    ///
    /// # Errors
    /// [`Stop`] when the script did not finish.
    pub fn run<'s, S, F>(&'s self, deadline: Instant, script: S) -> Result<F::Output, Stop>
    where
        S: FnOnce(&'s Shared) -> F,
        F: Future + 's,
    {
        // Leaked: the pendant's state lives as long as the board's `static` would, and
        // the runner's few hundred boots leak a few MB at most.
        let shared: &'s Shared = Box::leak(Box::new(Shared::new(procedure_config())));
        self.panel.borrow_mut().shown = None;
        self.link.to_pendant.clear();
        self.link.to_host.clear();
        let script = script(shared);
        exec::run(
            async {
                match select(self.pendant(shared), script).await {
                    Either::First(never) => never,
                    Either::Second(output) => output,
                }
            },
            deadline,
        )
    }
}
