//! One session in the real world, simulated and solved exactly as the pendant does
//! (`zerocal simulate`'s default): planned for the profile, captured twice per pose
//! with the closing reversal, solved, judged, its k = 2 budget made beside the hidden
//! truth; or another session of the same robot after a change (a moved zero, offsets
//! entered); and the ISO 9283-style positioning test after entering what it found.

use crate::error_sources::ErrorSource;
use crate::montecarlo::{self, Method};
use crate::positioning::{AccuracyReport, ArmError};
use crate::robot::SimRobot;
use crate::world::{RealSession, WorldConfig};
use std::fmt::Write as _;
use zerocal_core::plan::PlanError;
use zerocal_core::report::Verdict;
use zerocal_core::session::{budget, solve, Budget, SessionError, SessionSolution};
use zerocal_core::session::{BudgetTerm, SESSION_JOINTS};
use zerocal_profile::Profile;

/// Another session of the robot the first one drew, with the same pendant and
/// brackets (their calibrations kept), after a change to the robot.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Again {
    /// The seed of its noise, seats and bench.
    pub seed: u64,
    /// Joint J's reading reads this many degrees more at the same arm position than at
    /// the first session, as after a motor swap (J 2-6).
    pub zero_moved_deg: Vec<(usize, f64)>,
    /// The offsets entered into the controller since the first session, in the
    /// model's terms: Δθ2..Δθ6 (deg).
    pub entered_deg: Option<[f64; 5]>,
}

impl Again {
    /// The change on the simulated robot: a moved zero makes the reading larger at the
    /// same position (Δθ = true − reading falls), an entered offset moves the reading by
    /// itself (Δθ falls by it).
    pub fn change(&self) -> impl Fn(&mut SimRobot) + '_ {
        move |r| {
            for (joint, deg) in &self.zero_moved_deg {
                if let Some(o) = joint.checked_sub(1).and_then(|k| r.offsets_rad.get_mut(k)) {
                    *o -= deg.to_radians();
                }
            }
            for (o, e) in r.offsets_rad[1..]
                .iter_mut()
                .zip(self.entered_deg.iter().flatten())
            {
                *o -= e.to_radians();
            }
        }
    }
}

/// Why a session gave no solution.
#[derive(Debug)]
pub enum RunError {
    /// The profile's plan was refused.
    Plan(PlanError),
    /// This many captures left the sensor's range: the pendant refuses them.
    OutsideRange(usize),
    /// The session solver refused the session.
    Refused(SessionError),
}

impl std::fmt::Display for RunError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RunError::Plan(e) => write!(f, "plan: {e}"),
            RunError::OutsideRange(n) => write!(
                f,
                "{n} capture(s) left the SCL3300's mode-4 range of +/-10 deg: the pendant refuses them"
            ),
            RunError::Refused(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RunError {}

/// One real-world session, solved as the pendant does.
pub struct RealRun {
    /// The profile.
    pub profile: Profile,
    /// The session and its truth.
    pub session: RealSession,
    /// The solution.
    pub solution: SessionSolution<f64>,
    /// Its budget.
    pub budget: Budget<f64>,
    /// The verdict.
    pub verdict: Verdict,
}

impl RealRun {
    /// Simulates and solves one session of `poses` stage-2 poses on `profile`'s robot
    /// drawn from `seed`, or, with `again`, that robot's next session after its change.
    ///
    /// # Errors
    /// The plan refused, captures outside the sensor's range, the session refused.
    pub fn simulate(
        profile: Profile,
        world: &WorldConfig,
        poses: usize,
        seed: u64,
        again: Option<&Again>,
    ) -> Result<RealRun, RunError> {
        let (plan, fit) =
            montecarlo::setup(&profile, Method::Compensated, poses).map_err(RunError::Plan)?;
        let first = RealSession::simulate(&profile, &plan, world, seed);
        let session = match again {
            Some(a) => first.again(&profile, &plan, world, a.seed, a.change()),
            None => first,
        };
        let readings = session.readings(&profile, world);
        if session.outside_range > 0 {
            return Err(RunError::OutsideRange(session.outside_range));
        }
        let outcome = solve(&readings, &fit);
        let solution = outcome.result.map_err(RunError::Refused)?;
        let verdict = Verdict::judge(&solution.fit, &fit, outcome.stage1.as_ref());
        let budget = budget(
            &solution,
            &session.poses,
            &world.budget_inputs(&profile, &fit, &session.brackets),
        );
        Ok(RealRun {
            profile,
            session,
            solution,
            budget,
            verdict,
        })
    }

    /// The ISO 9283-style test on the robot: flange position error at `points` seeded
    /// random poses within its limits, with the hidden offsets and after entering the
    /// found ones.
    ///
    /// # Errors
    /// A profile without lengths (no positions to test), its workspace unreachable.
    pub fn accuracy(&self, points: usize, seed: u64) -> Result<AccuracyReport, ArmError> {
        let p = &self.profile;
        let limits = core::array::from_fn(|k| (p.joints[k].min_deg, p.joints[k].max_deg));
        let mut found = [0.0; 6];
        found[1..].copy_from_slice(&self.solution.offsets_rad);
        crate::positioning::accuracy_test(
            &p.title,
            &p.arm,
            &limits,
            &self.session.robot.offsets_rad,
            &found,
            points,
            seed,
        )
    }

    /// The report of this session beside its truth (`zerocal simulate`'s): what was
    /// switched on, the offsets found against the truth with their k = 2, the budget.
    pub fn report(&self, world: &WorldConfig, seed: u64) -> String {
        let run = self;
        let mut out = String::new();
        let s = &run.solution;
        let truth = run.session.truth_rad();
        let off: Vec<&str> = ErrorSource::ALL
            .iter()
            .filter(|src| !src.is_on(world))
            .map(|src| src.label())
            .collect();
        let _ = writeln!(
            out,
            "zerocal simulate: {} ({}), seed {seed}, real world: {}",
            run.profile.name,
            run.profile.title,
            if off.is_empty() {
                "every error source on".to_owned()
            } else {
                format!("without {}", off.join("; "))
            }
        );
        let _ = writeln!(
            out,
            "{} captures ({} poses, each from both sides of the backlash), residual RMS {:.5} deg, condition number {:.1}",
            run.session.poses.len(),
            s.fit.poses,
            s.fit.residual_rms_rad.to_degrees(),
            s.fit.condition_number
        );
        let _ = writeln!(
            out,
            "\njoint  found_deg   truth_deg   error_deg   1sigma_deg  U(k=2)_deg  |error|/U"
        );
        for (k, t) in truth.iter().enumerate().take(SESSION_JOINTS) {
            let f = s.offsets_rad[k].to_degrees();
            let t = t.to_degrees();
            let u = run.budget.expanded_rad[k].to_degrees();
            let _ = writeln!(
                out,
                "j{}     {f:+.5}    {t:+.5}    {:+.5}    {:.5}     {u:.5}     {:.2}",
                k + 2,
                f - t,
                s.sigma_rad()[k].to_degrees(),
                (f - t).abs() / u
            );
        }
        let _ = writeln!(out, "\nbudget (standard uncertainties, deg):");
        for (term, u) in BudgetTerm::ALL.iter().zip(&run.budget.terms_rad) {
            let cols: Vec<String> = u.iter().map(|v| format!("{:.5}", v.to_degrees())).collect();
            let _ = writeln!(out, "  {:<42} {}", term.name(), cols.join("  "));
        }
        if run.verdict.is_pass() {
            let _ = writeln!(out, "verdict: PASS");
        }
        for w in &run.verdict.warnings {
            let _ = writeln!(out, "verdict: WARN {w}");
        }
        out
    }
}
