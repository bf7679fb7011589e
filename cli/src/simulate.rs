//! `zerocal simulate`: the main job on an embedded default. A simulated robot (a robot
//! profile's kinematics) with hidden offsets, base tilt and sensor bias goes through
//! stages 0-2 exactly as the pendant would take it, and the pendant's report is printed
//! beside the hidden truth, then the positioning test on the same robot.

use clap::Args;
use std::fmt::Write;
use zerocal_core::model::Convention;
use zerocal_core::real::deg_to_rad;
use zerocal_core::report::{write_report, Verdict};
use zerocal_inputs::args::{CountIn, RealIn, SEED};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;
use zerocal_sim::positioning::{self, AccuracyReport};
use zerocal_sim::session::{fit_config_for, SessionConfig, SessionResult};
use zerocal_sim::{Noise, SimSession};

/// `--noise-deg`'s range (deg): from a millionth of a degree, where noise still sets
/// the fit's error rather than rounding, to 1°.
pub const NOISE_DEG: RealIn = RealIn::closed(1e-6, 1.0, "deg");

/// Which world `zerocal simulate` simulates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum World {
    /// Every sourced error of a real sensor and robot.
    Real,
    /// The paper's ideal sensor on a rigid robot.
    Ideal,
}

/// Arguments of `zerocal simulate`.
#[derive(Args, Debug, Clone)]
pub struct SimulateArgs {
    /// Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file.
    #[arg(long, value_name = "NAME", default_value = "kuka-kr6-r900-sixx")]
    pub robot: String,
    /// Seed of the hidden truth, the poses and the noise. Range: [0, 18446744073709551615].
    #[arg(long, default_value_t = 1, value_parser = SEED)]
    pub seed: u64,
    /// The world simulated: `real` (a production SCL3300 and a robot that sags, has
    /// backlash and repeats only so well, every source on unless `--without` says) or
    /// `ideal` (the paper's: a constant bias plus uniform noise on a rigid robot).
    #[arg(long, value_enum, default_value = "real")]
    pub world: World,
    /// The real world's sources and faults.
    #[command(flatten)]
    pub real: crate::world_args::WorldArgs,
    /// Stage-2 poses (real world: each captured twice, default 40 and the plan's 3
    /// revisits; ideal: default 30).
    /// Range: [4, 10000].
    #[arg(long, value_parser = CountIn::<usize>::new(4, 10_000))]
    pub poses: Option<usize>,
    /// Ideal world: reading noise, uniform in ±A degrees (the paper's Table 4: 0.002).
    /// Below a millionth of a degree rounding, not noise, sets the fit's error and its
    /// 1-sigma, and the report's ratios (error/1-sigma, the accuracy gain) would divide
    /// rounding by rounding. Range: [0.000001, 1] deg.
    #[arg(long, default_value_t = 0.002, value_name = "A", value_parser = NOISE_DEG)]
    pub noise_deg: f64,
    /// Ideal world: sensor convention of the simulated sensor and of the model (the
    /// real world's SCL3300 is `axis`).
    #[arg(long, default_value = "rpy", value_parser = zerocal_inputs::args::convention())]
    pub convention: Convention,
    /// Joints 3-6 are drawn within ±this (deg), and within the robot's limits.
    /// Range: (0, 180] deg.
    #[arg(long, default_value_t = 180.0, value_parser = RealIn::above(0.0, 180.0, "deg"))]
    pub joint_range_deg: f64,
    /// Hidden offsets of joints 2-6 are drawn within ±this (deg). Range: [0, 10] deg.
    #[arg(long, default_value_t = 0.5, value_parser = RealIn::closed(0.0, 10.0, "deg"))]
    pub max_offset_deg: f64,
    /// Skip stage 0: Δθ2 then includes the sensor's x bias, as in the paper.
    #[arg(long)]
    pub no_stage0: bool,
    /// Write SVG plots (TCP error per test point before/after along X, Y, Z, and the
    /// identification residuals) into this directory.
    #[arg(long, value_name = "DIR")]
    pub plot: Option<std::path::PathBuf>,
    /// Test points of the ISO 9283-style accuracy test on the robot (a profile with
    /// lengths).
    /// Range: [1, 100000].
    #[arg(long, default_value_t = 200, value_parser = CountIn::<usize>::new(1, 100_000))]
    pub accuracy_points: usize,
}

impl SimulateArgs {
    /// The reading noise the flags ask for.
    pub fn noise(&self) -> Noise {
        Noise::Uniform {
            half_width_rad: deg_to_rad(self.noise_deg),
        }
    }

    /// The session the flags describe.
    ///
    /// The ranges are checked when the flags are parsed (`zerocal_inputs::args`).
    pub fn session_config(&self, profile: &Profile) -> Result<SessionConfig, CliError> {
        let r = self.joint_range_deg;
        let wrist_limits_deg = core::array::from_fn(|k| {
            let j = &profile.joints[k + 2];
            (j.min_deg.max(-r), j.max_deg.min(r))
        });
        // The paper's robot keeps its own stage 1 (joint 2 drawn, turning either way).
        let paper = profile.name == "paper-wrist";
        Ok(SessionConfig {
            arm: (!paper).then_some(profile.arm),
            stage1_joints_rad: (!paper).then_some(profile.stage1_joints_rad),
            wrist_limits_deg: Some(wrist_limits_deg),
            seed: self.seed,
            poses: self.poses.unwrap_or(30),
            noise: self.noise(),
            convention: self.convention,
            joint_range_deg: self.joint_range_deg,
            max_offset_deg: self.max_offset_deg,
            with_stage0: !self.no_stage0,
            ..SessionConfig::default()
        })
    }
}

/// Simulates and identifies.
pub fn simulate(args: &SimulateArgs) -> Result<(Profile, SimSession, SessionResult), CliError> {
    let profile = zerocal_inputs::robot::load(&args.robot)?;
    let cfg = args.session_config(&profile)?;
    let session = SimSession::simulate(&cfg).map_err(|e| CliError::Refused(e.to_string()))?;
    let result = session
        .identify(&fit_config_for(cfg.noise))
        .map_err(|e| CliError::Refused(e.to_string()))?;
    Ok((profile, session, result))
}

/// The report: the pendant's view, then the hidden truth beside it.
pub fn render(
    args: &SimulateArgs,
    session: &SimSession,
    result: &SessionResult,
) -> Result<String, CliError> {
    let cfg = fit_config_for(args.noise());
    let verdict = Verdict::judge(&result.fit, &cfg, Some(&result.stage1));
    let mut out = String::new();
    let fmt_err = |e: std::fmt::Error| CliError::Input(e.to_string());
    writeln!(
        out,
        "zerocal simulate: {}, seed {}, {} poses, noise +/-{} deg, {} convention, joints within +/-{} deg",
        args.robot,
        args.seed,
        args.poses.unwrap_or(30),
        args.noise_deg,
        args.convention.name(),
        args.joint_range_deg
    )
    .map_err(fmt_err)?;
    if let Some(b) = result.bias {
        let (x, y) = b.to_deg();
        writeln!(out, "stage 0: sensor bias x {x:+.5} deg, y {y:+.5} deg").map_err(fmt_err)?;
    } else {
        writeln!(out, "stage 0: skipped").map_err(fmt_err)?;
    }
    writeln!(out, "\n-- pendant report --").map_err(fmt_err)?;
    write_report(&mut out, Some(&result.stage1), &result.fit, &verdict).map_err(fmt_err)?;

    writeln!(out, "\n-- against the hidden truth --").map_err(fmt_err)?;
    writeln!(
        out,
        "joint  identified_deg  truth_deg   error_deg   error/1sigma"
    )
    .map_err(fmt_err)?;
    let dt2 = result.stage1.delta_theta2_rad.to_degrees();
    let t2 = session.robot.delta_theta2_rad().to_degrees();
    let s2 = result
        .stage1
        .delta_theta2_sigma_rad(result.fit.noise_sigma_rad)
        .to_degrees();
    writeln!(
        out,
        "j2     {dt2:+.5}        {t2:+.5}    {:+.6}   {:+.2}  (stage 1)",
        dt2 - t2,
        (dt2 - t2) / s2
    )
    .map_err(fmt_err)?;
    for k in 0..4 {
        let found = result.fit.offsets_rad[k].to_degrees();
        let truth = session.robot.wrist_offsets_rad()[k].to_degrees();
        let sigma = result.fit.sigma_rad[k].to_degrees();
        writeln!(
            out,
            "j{}     {found:+.5}        {truth:+.5}    {:+.6}   {:+.2}",
            k + 3,
            found - truth,
            (found - truth) / sigma
        )
        .map_err(fmt_err)?;
    }
    let tb = session.robot.base_tilt;
    writeln!(
        out,
        "base tilt truth alpha {:+.5} deg, beta {:+.5} deg; sensor bias truth x {:+.5} deg, y {:+.5} deg",
        tb.alpha_rad.to_degrees(),
        tb.beta_rad.to_degrees(),
        session.sensor.model.bias.x_rad.to_degrees(),
        session.sensor.model.bias.y_rad.to_degrees()
    )
    .map_err(fmt_err)?;
    Ok(out)
}

/// The ISO 9283-style test on the robot: flange position error at seeded random
/// poses within its limits with the hidden offsets, and after entering the identified
/// ones.
pub fn accuracy(
    args: &SimulateArgs,
    profile: &Profile,
    session: &SimSession,
    result: &SessionResult,
) -> Result<AccuracyReport, CliError> {
    let limits = core::array::from_fn(|k| (profile.joints[k].min_deg, profile.joints[k].max_deg));
    let mut found = [0.0; 6];
    found[1..].copy_from_slice(&result.solution.offsets_rad);
    positioning::accuracy_test(
        &profile.title,
        &profile.arm,
        &limits,
        &session.robot.offsets_rad,
        &found,
        args.accuracy_points,
        args.seed,
    )
    .map_err(|e| CliError::Refused(format!("accuracy test: {e}")))
}

/// Writes the plots of `--plot DIR`; returns the files written.
pub fn plots(
    dir: &std::path::Path,
    session: &SimSession,
    result: &SessionResult,
    report: &AccuracyReport,
) -> Result<Vec<std::path::PathBuf>, CliError> {
    let res =
        zerocal_analysis::plots::residuals(&result.model, &session.poses, &result.fit.offsets_rad);
    zerocal_analysis::plots::write_plots(dir, report, &res)
        .map_err(|e| CliError::Input(format!("{}: {e}", dir.display())))
}
