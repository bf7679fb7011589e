//! A robot whose true joint zeros differ from its controller's by hidden offsets, and
//! which, like a real one, sags under gravity, has backlash in its gears and does not
//! repeat a pose exactly ([`RobotErrors`]).

use nalgebra::{Rotation3, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use zerocal_core::model::{Arm, BaseTilt, JointAxis, JOINTS, WRIST_JOINTS};
use zerocal_core::real::deg_to_rad;
use zerocal_core::stage2::geometry::MIN_SAG_LEVER_M;
use zerocal_core::stage2::{MassModel, GRAVITY_M_S2};

/// Which of the robot's error sources are on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RobotSources {
    /// Gravity sag of joints 2 and 3.
    pub sag: bool,
    /// Gear backlash (lost motion).
    pub backlash: bool,
    /// Pose repeatability.
    pub repeatability: bool,
    /// Joint axes off their nominal directions ([`RobotSpec::misalignment_perpendicular_deg`]).
    pub misalignment: bool,
    /// Angle-dependent gear transmission error ([`RobotSpec::transmission_pp_deg`]).
    pub transmission: bool,
    /// Gravity deflection of joints 4, 5, 6 ([`RobotSpec::wrist_sag_full_lever_deg`]).
    pub wrist_compliance: bool,
}

impl RobotSources {
    /// The default: sag, backlash and repeatability on; the real-arm sources
    /// (misalignment, transmission error, wrist compliance) off.
    pub const ALL: RobotSources = RobotSources {
        sag: true,
        backlash: true,
        repeatability: true,
        misalignment: false,
        transmission: false,
        wrist_compliance: false,
    };
    /// Every source on, the real-arm ones too.
    pub const REAL_ARM: RobotSources = RobotSources {
        misalignment: true,
        transmission: true,
        wrist_compliance: true,
        ..RobotSources::ALL
    };
    /// A rigid, backlash-free, perfectly repeatable robot.
    pub const NONE: RobotSources = RobotSources {
        sag: false,
        backlash: false,
        repeatability: false,
        misalignment: false,
        transmission: false,
        wrist_compliance: false,
    };
}

/// The ranges a robot's errors are drawn from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobotSpec {
    /// Sag of joints 2 and 3 at the largest gravity torque the arm sees (deg), drawn
    /// per joint within this range: the stated figure ("0.01-0.02° at full lever"). No
    /// public compliance of a named arm was found (docs/error-budget.md): joint
    /// stiffness papers (Dumas et al.; Klimchik et al.) were not reachable.
    pub sag_full_lever_deg: (f64, f64),
    /// Lost motion per joint (deg), drawn within 0..this: < 1 arc min for an RV gear
    /// (Nabtesco RV-42N product page: lost motion < 1 arc min) and of the same order for
    /// Harmonic Drive gears (CSF catalogue, Table 40: 1 arc min transmission accuracy).
    pub lost_motion_deg: f64,
    /// Gravity torque, as a fraction of the joint's largest, below which friction holds
    /// the output on the side it was driven to (approach) rather than gravity's side.
    /// A stated default: no source gives it.
    pub friction_fraction: f64,
    /// Repeatability per joint, 1σ (deg): the stated 0.0015° per joint; six joints so
    /// give about 0.004° of flange orientation, within the 87 µrad (0.005°) measured
    /// for an ABB IRB 1600 (Slamani, Nubiola and Bonev, Industrial Robot 39(1), 2012).
    pub repeatability_deg: f64,
    /// Mass of the pendant and its bracket (kg) and its centre in the flange frame (m):
    /// the pendant's own design figure.
    pub pendant_kg: f64,
    /// Mass of a tool on the flange (kg), lumped at the pendant's centre. Default 0:
    /// a stated default (the pendant is calibrated with the flange bare).
    pub tool_kg: f64,
    /// Rotation of each joint's axis off its nominal direction, perpendicular to it and
    /// never about the previous joint's axis (that is the previous joint's zero), drawn
    /// per joint within this range (deg) where the two axes are perpendicular: Universal
    /// Robots' factory calibrations in their ROS drivers' examples (twist deviations
    /// 0.01-0.05°); a FANUC R-2000iC/165F laser-tracker data set (Boby and Klimchik,
    /// Robotics and Computer-Integrated Manufacturing) gives 0.005-0.022°.
    pub misalignment_perpendicular_deg: (f64, f64),
    /// The same where the two axes are parallel (J2-J3; J3-J4 on a UR): UR's
    /// calibrations give 0.07-0.7° between J2-J3-J4, the FANUC data 0.010-0.016°.
    pub misalignment_parallel_deg: (f64, f64),
    /// Transmission error per joint, peak to peak over a turn (deg): harmonics 1 and 2
    /// of the joint angle (each of drawn weight and phase), harmonics 3 and 4 up to
    /// [`RobotSpec::higher_harmonic_share`] of the larger of those, scaled together to
    /// a peak to peak drawn in this range, and a ripple many times a turn
    /// ([`RobotSpec::ripple_deg`]). The FANUC data: J2, J3, J5 0.03-0.06° over their
    /// swept ranges, once and twice per turn.
    pub transmission_pp_deg: (f64, f64),
    /// Harmonics 3 and 4 of a joint's transmission error, each up to this share of the
    /// larger of harmonics 1 and 2: a stated range (no public spectrum of a robot
    /// reducer's error beyond twice a turn was found), the budget's
    /// [`zerocal_core::stage2::transmission::HIGHER_HARMONIC_SHARE`].
    pub higher_harmonic_share: f64,
    /// A ripple of each reducer many times a turn (20-60 cycles: a cycloid's pins, a
    /// strain wave's teeth seen through the output), amplitude up to this (deg): a stated
    /// range, below one capture's noise; the fit cannot follow it and need not (the
    /// poses sample it at unrelated phases).
    pub ripple_deg: f64,
    /// Once-per-turn error of joints 4 and 6, peak to peak (deg): the FANUC data's
    /// 0.023-0.027°.
    pub once_per_turn_pp_deg: (f64, f64),
    /// Deflection of joints 4, 5, 6 at the largest gravity torque of the links after
    /// them, pendant and tool (deg): a stated range, no public wrist stiffness was found.
    pub wrist_sag_full_lever_deg: (f64, f64),
}

impl RobotSpec {
    /// The figures above.
    pub const DEFAULT: RobotSpec = RobotSpec {
        sag_full_lever_deg: (0.01, 0.02),
        lost_motion_deg: 1.0 / 60.0,
        friction_fraction: 0.1,
        repeatability_deg: 0.0015,
        pendant_kg: zerocal_core::stage2::PENDANT_KG,
        tool_kg: 0.0,
        misalignment_perpendicular_deg: (0.01, 0.05),
        misalignment_parallel_deg: (0.01, 0.5),
        transmission_pp_deg: (0.005, 0.03),
        higher_harmonic_share: zerocal_core::stage2::transmission::HIGHER_HARMONIC_SHARE,
        ripple_deg: zerocal_core::stage2::transmission::RIPPLE_MAX_DEG,
        once_per_turn_pp_deg: (0.005, 0.025),
        wrist_sag_full_lever_deg: (0.01, 0.03),
    };

    /// The FANUC R-2000iC/165F laser-tracker figures (Boby and Klimchik, see the
    /// fields): misalignments 0.005-0.022° (perpendicular) and 0.010-0.016° (J2-J3),
    /// transmission error 0.03-0.06° p-p, once-per-turn 0.023-0.027°, hysteresis
    /// (lost motion) up to 0.03°. For use with the fanuc-m20ia profile.
    pub const FANUC_AS_MEASURED: RobotSpec = RobotSpec {
        lost_motion_deg: 0.03,
        misalignment_perpendicular_deg: (0.005, 0.022),
        misalignment_parallel_deg: (0.010, 0.016),
        transmission_pp_deg: (0.03, 0.06),
        once_per_turn_pp_deg: (0.023, 0.027),
        ..RobotSpec::DEFAULT
    };
}

/// One robot's errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobotErrors {
    /// Compliance of each joint (rad per N·m); only joints 2 and 3 sag here.
    pub compliance_rad_per_nm: [f64; JOINTS],
    /// The true masses (kg) the sag comes from.
    pub masses: Option<MassModel<f64>>,
    /// Largest gravity torque of each joint over its range (N·m).
    pub full_torque_nm: [f64; JOINTS],
    /// Lost motion per joint (rad).
    pub lost_motion_rad: [f64; JOINTS],
    /// Friction threshold as a fraction of `full_torque_nm`.
    pub friction_fraction: f64,
    /// Repeatability per joint, 1σ (rad).
    pub repeatability_rad: f64,
    /// Transmission error per joint: (harmonic order, amplitude rad, phase rad).
    pub transmission: [[Harmonic; TRANSMISSION_TERMS]; JOINTS],
}

/// One term of a transmission error: `amplitude_rad · sin(order · q + phase_rad)`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Harmonic {
    /// Cycles per joint turn.
    pub order: f64,
    /// Amplitude (rad).
    pub amplitude_rad: f64,
    /// Phase (rad).
    pub phase_rad: f64,
}

/// Harmonics 1-4, the ripple and the once-per-turn term of joints 4 and 6.
pub const TRANSMISSION_TERMS: usize = 6;

impl RobotErrors {
    /// None at all.
    pub fn none() -> Self {
        RobotErrors {
            compliance_rad_per_nm: [0.0; JOINTS],
            masses: None,
            full_torque_nm: [0.0; JOINTS],
            lost_motion_rad: [0.0; JOINTS],
            friction_fraction: 0.0,
            repeatability_rad: 0.0,
            transmission: [[Harmonic::default(); TRANSMISSION_TERMS]; JOINTS],
        }
    }

    /// Errors drawn for `arm`: masses from `masses` (the profile's, or uniform per
    /// metre) each scaled by a factor in 0.7..1.3 (the true arm is not the model's), the
    /// pendant added at the flange, and the compliances that give the drawn sag at the
    /// largest torque found over a grid of joints 2 and 3 within `limits_rad`.
    pub fn draw(
        arm: &Arm<f64>,
        masses: Option<MassModel<f64>>,
        limits_rad: &[(f64, f64); JOINTS],
        spec: &RobotSpec,
        sources: RobotSources,
        rng: &mut ChaCha8Rng,
    ) -> Self {
        let mut e = RobotErrors::none();
        e.friction_fraction = spec.friction_fraction;
        if sources.repeatability {
            e.repeatability_rad = deg_to_rad(spec.repeatability_deg);
        }
        if sources.backlash {
            for l in &mut e.lost_motion_rad {
                *l = deg_to_rad(rng.gen_range(0.0..=spec.lost_motion_deg));
            }
        }
        if let Some(mut m) = masses {
            for kg in &mut m.link_kg {
                *kg *= rng.gen_range(0.7..=1.3);
            }
            // The pendant hangs out from the flange (its design figure), the tool
            // lumped with it.
            m.pendant_kg = spec.pendant_kg + spec.tool_kg;
            m.pendant_com_m = Vector3::new(0.0, 0.0, zerocal_core::stage2::PENDANT_COM_M);
            e.masses = Some(m);
            e.full_torque_nm = full_torques(arm, &m, limits_rad);
            // Friction holds the wrist (light loads) wherever it was driven; joints 2-3
            // are the loaded ones.
            if sources.sag {
                for k in [1, 2] {
                    let (lo, hi) = spec.sag_full_lever_deg;
                    if e.full_torque_nm[k] > 0.0 {
                        e.compliance_rad_per_nm[k] =
                            deg_to_rad(rng.gen_range(lo..=hi)) / e.full_torque_nm[k];
                    }
                }
            }
            if sources.wrist_compliance {
                let wrist = wrist_full_torques(arm, &m, limits_rad);
                let (lo, hi) = spec.wrist_sag_full_lever_deg;
                for (k, torque) in wrist.iter().enumerate().skip(3) {
                    e.full_torque_nm[k] = *torque;
                    if *torque > 0.0 {
                        let drawn = deg_to_rad(rng.gen_range(lo..=hi));
                        // A joint whose load hangs on its axis (joint 6 under the
                        // pendant; a torque of rounding, such as the GP7's flange π
                        // written to seven decimals gives) bears none: no compliance
                        // turns it into a deflection (the fit's own floor). Drawn all the
                        // same, so that the other joints' draws stay as they were.
                        let load_kg = m.link_kg[k..].iter().sum::<f64>() + m.pendant_kg;
                        let floor_nm = load_kg * GRAVITY_M_S2 * MIN_SAG_LEVER_M;
                        if *torque > floor_nm {
                            e.compliance_rad_per_nm[k] = drawn / torque;
                        } else {
                            e.full_torque_nm[k] = 0.0;
                        }
                    }
                }
            }
        }
        if sources.transmission {
            for (k, terms) in e.transmission.iter_mut().enumerate() {
                *terms = draw_transmission(k, spec, rng);
            }
        }
        e
    }

    /// The transmission error of joint `k` at true angle `q_rad` (rad).
    pub fn transmission_error_rad(&self, k: usize, q_rad: f64) -> f64 {
        self.transmission
            .get(k)
            .map_or(0.0, |terms| harmonic_sum(terms, q_rad))
    }

    /// The gravity torque about each joint's axis at true angles `q_rad` (N·m), the
    /// base level: [`MassModel::gravity_torques_nm`] of these masses; zero without.
    pub fn gravity_torques_nm(&self, arm: &Arm<f64>, q_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        match &self.masses {
            Some(m) => m.gravity_torques_nm(arm, q_rad),
            None => [0.0; JOINTS],
        }
    }

    /// Where each joint settles without backlash or scatter, at commanded `q_cmd_rad`
    /// (the nominal model's angles the controller drives to) with `residual_offsets_rad`
    /// (true − entered zero, per joint) left over: the angle `q + residual`, plus gravity
    /// sag (compliance × gravity torque there) and the transmission error there. Backlash
    /// sits at the middle of its play (0) and repeatability adds no scatter: the
    /// deterministic robot of the TCP test ([`crate::tcp`]).
    pub fn true_joints_rad(
        &self,
        arm: &Arm<f64>,
        q_cmd_rad: &[f64; JOINTS],
        residual_offsets_rad: &[f64; JOINTS],
    ) -> [f64; JOINTS] {
        let q: [f64; JOINTS] = core::array::from_fn(|k| q_cmd_rad[k] + residual_offsets_rad[k]);
        self.settle(arm, &q).0
    }

    /// The angles at true angles `q_rad` after sag and transmission error, and the
    /// gravity torques there (N·m), which also decide the side of the backlash.
    fn settle(&self, arm: &Arm<f64>, q_rad: &[f64; JOINTS]) -> ([f64; JOINTS], [f64; JOINTS]) {
        let tau = self.gravity_torques_nm(arm, q_rad);
        let settled = core::array::from_fn(|k| {
            q_rad[k]
                + self.compliance_rad_per_nm[k] * tau[k]
                + self.transmission_error_rad(k, q_rad[k])
        });
        (settled, tau)
    }

    /// Where each joint really is, for a commanded pose reached with the given approach
    /// directions (+1: the joint arrived moving positive), its zero already applied
    /// (`q_rad` = commanded + offset): sag and transmission error
    /// ([`Self::true_joints_rad`]), then the side of the backlash and repeatability.
    pub fn deflect(
        &self,
        arm: &Arm<f64>,
        q_rad: &[f64; JOINTS],
        approach: &[i8; JOINTS],
        rng: &mut ChaCha8Rng,
    ) -> [f64; JOINTS] {
        let (settled, tau) = self.settle(arm, q_rad);
        core::array::from_fn(|k| {
            // The output lags the motor by half the lost motion on the side it was
            // driven from, unless gravity pulls it across to its own side.
            let loaded = LOADED_JOINTS.contains(&k);
            let side = if loaded
                && self.full_torque_nm[k] > 0.0
                && tau[k].abs() > self.friction_fraction * self.full_torque_nm[k]
            {
                tau[k].signum()
            } else {
                -f64::from(approach[k].signum())
            };
            let backlash = 0.5 * self.lost_motion_rad[k] * side;
            let z: f64 = StandardNormal.sample(rng);
            settled[k] + backlash + self.repeatability_rad * z
        })
    }
}

/// Joints 2 and 3 (indices 1, 2) carry the arm: gravity can pull their output across
/// the play. The wrist joints carry the wrist and a 0.25 kg pendant: friction holds
/// them on the side they were driven to (a stated model, no source gives the
/// threshold).
const LOADED_JOINTS: [usize; 2] = [1, 2];

/// The largest |torque| of each joint over a grid of joints 2 and 3 in their limits
/// (the others at zero: the loaded joints' worst case is the arm stretched out).
fn full_torques(
    arm: &Arm<f64>,
    m: &MassModel<f64>,
    limits_rad: &[(f64, f64); JOINTS],
) -> [f64; JOINTS] {
    let mut worst = [0.0f64; JOINTS];
    let steps = 36;
    for a in 0..=steps {
        for b in 0..=steps {
            let mut q = [0.0; JOINTS];
            let at = |(lo, hi): (f64, f64), i: usize| lo + (hi - lo) * i as f64 / steps as f64;
            q[1] = at(limits_rad[1], a);
            q[2] = at(limits_rad[2], b);
            for (w, t) in worst.iter_mut().zip(m.gravity_torques_nm(arm, &q)) {
                *w = w.max(t.abs());
            }
        }
    }
    worst
}

fn harmonic_sum(terms: &[Harmonic], q_rad: f64) -> f64 {
    terms
        .iter()
        .map(|h| h.amplitude_rad * (h.order * q_rad + h.phase_rad).sin())
        .sum()
}

/// Peak to peak of a harmonic sum over one turn, sampled every 0.5°.
pub fn peak_to_peak_rad(terms: &[Harmonic]) -> f64 {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..720 {
        let v = harmonic_sum(terms, core::f64::consts::TAU * f64::from(i) / 720.0);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    hi - lo
}

/// Joint `k`'s transmission error: harmonics 1 and 2 with drawn weights and phases,
/// harmonics 3 and 4 up to [`RobotSpec::higher_harmonic_share`] of the larger, all
/// scaled to a drawn peak to peak; a ripple of 20-60 cycles a turn; on joints 4 and 6
/// (indices 3, 5) a once-per-turn term too (the wrist twisting under gravity).
fn draw_transmission(
    k: usize,
    spec: &RobotSpec,
    rng: &mut ChaCha8Rng,
) -> [Harmonic; TRANSMISSION_TERMS] {
    let mut terms = [Harmonic::default(); TRANSMISSION_TERMS];
    let phase = |rng: &mut ChaCha8Rng| rng.gen_range(0.0..core::f64::consts::TAU);
    let low: [f64; 2] = [rng.gen_range(0.2..=1.0), rng.gen_range(0.2..=1.0)];
    let top = low[0].max(low[1]);
    for (i, order) in [1.0, 2.0, 3.0, 4.0].into_iter().enumerate() {
        let weight = if i < 2 {
            low[i]
        } else {
            top * rng.gen_range(0.0..=spec.higher_harmonic_share)
        };
        terms[i] = Harmonic {
            order,
            amplitude_rad: weight,
            phase_rad: phase(rng),
        };
    }
    let (lo, hi) = spec.transmission_pp_deg;
    let scale = deg_to_rad(rng.gen_range(lo..=hi)) / peak_to_peak_rad(&terms[..4]);
    for h in &mut terms[..4] {
        h.amplitude_rad *= scale;
    }
    terms[4] = Harmonic {
        order: f64::from(rng.gen_range(20u8..=60)),
        amplitude_rad: deg_to_rad(rng.gen_range(0.0..=spec.ripple_deg)),
        phase_rad: phase(rng),
    };
    if k == 3 || k == 5 {
        let (lo, hi) = spec.once_per_turn_pp_deg;
        terms[5] = Harmonic {
            order: 1.0,
            amplitude_rad: 0.5 * deg_to_rad(rng.gen_range(lo..=hi)),
            phase_rad: phase(rng),
        };
    }
    terms
}

/// The largest |torque| of the wrist joints over a grid of joints 3, 4 and 5 in their
/// limits: the wrist's lever is longest with its links horizontal.
fn wrist_full_torques(
    arm: &Arm<f64>,
    m: &MassModel<f64>,
    limits_rad: &[(f64, f64); JOINTS],
) -> [f64; JOINTS] {
    let mut worst = [0.0f64; JOINTS];
    let steps = 12;
    let at = |(lo, hi): (f64, f64), i: usize| lo + (hi - lo) * i as f64 / steps as f64;
    for a in 0..=steps {
        for b in 0..=steps {
            for c in 0..=steps {
                let mut q = [0.0; JOINTS];
                q[2] = at(limits_rad[2], a);
                q[3] = at(limits_rad[3], b);
                q[4] = at(limits_rad[4], c);
                for (w, t) in worst.iter_mut().zip(m.gravity_torques_nm(arm, &q)) {
                    *w = w.max(t.abs());
                }
            }
        }
    }
    worst
}

/// `arm` with each joint's axis (joints 2-6) turned off its nominal direction by a
/// drawn angle about a direction perpendicular to it and to the previous joint's axis
/// (a turn about that one is the previous joint's zero); where the two axes are
/// parallel, about a drawn direction perpendicular to both. Returns the arm and the
/// drawn angles (rad).
pub fn misalign(
    arm: &Arm<f64>,
    spec: &RobotSpec,
    rng: &mut ChaCha8Rng,
) -> (Arm<f64>, [f64; JOINTS]) {
    let mut out = *arm;
    let mut angles = [0.0; JOINTS];
    #[allow(clippy::needless_range_loop)] // joint k and joint k - 1 together
    for k in 1..JOINTS {
        let axis = arm.joints[k].axis.unit::<f64>();
        // The previous axis in this joint's frame (before its own turn).
        let prev = arm.joints[k].origin.rotation.inverse() * arm.joints[k - 1].axis.unit::<f64>();
        let cross = axis.cross(&prev);
        let parallel = cross.norm() < 1e-9;
        let (lo, hi) = if parallel {
            spec.misalignment_parallel_deg
        } else {
            spec.misalignment_perpendicular_deg
        };
        let angle = deg_to_rad(rng.gen_range(lo..=hi)) * if rng.gen::<bool>() { 1.0 } else { -1.0 };
        let about = if parallel {
            // Any direction perpendicular to the axis.
            let helper = if axis.x.abs() < 0.9 {
                Vector3::x()
            } else {
                Vector3::y()
            };
            let u = axis.cross(&helper).normalize();
            let v = axis.cross(&u);
            let t: f64 = rng.gen_range(0.0..core::f64::consts::TAU);
            u * t.cos() + v * t.sin()
        } else {
            cross.normalize()
        };
        let tilt = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(about), angle);
        out.joints[k].origin.rotation = arm.joints[k].origin.rotation * tilt;
        angles[k] = angle.abs();
    }
    (out, angles)
}

/// The robot as the world sees it: true offsets and base tilt, unknown to the pendant.
#[derive(Clone, Copy, Debug)]
pub struct SimRobot {
    /// The arm and the pendant's two brackets.
    pub arm: Arm<f64>,
    /// True base tilt.
    pub base_tilt: BaseTilt<f64>,
    /// True Δθ1..Δθ6 = true − commanded (rad). Δθ1 turns about the vertical: no
    /// inclinometer sees it.
    pub offsets_rad: [f64; JOINTS],
    /// Sag, backlash and repeatability.
    pub errors: RobotErrors,
}

impl SimRobot {
    /// The paper's robot with the given truth (degrees): Δθ3..Δθ6 and the base tilt.
    pub fn paper(offsets_deg: [f64; WRIST_JOINTS], base_tilt_deg: (f64, f64)) -> Self {
        let mut offsets_rad = [0.0; JOINTS];
        for (o, d) in offsets_rad[2..].iter_mut().zip(offsets_deg) {
            *o = deg_to_rad(d);
        }
        SimRobot {
            arm: Arm::paper(),
            base_tilt: BaseTilt::from_deg(base_tilt_deg.0, base_tilt_deg.1),
            offsets_rad,
            errors: RobotErrors::none(),
        }
    }

    /// Δθ2 (rad).
    pub fn delta_theta2_rad(&self) -> f64 {
        self.offsets_rad[1]
    }

    /// Δθ3..Δθ6 (rad).
    pub fn wrist_offsets_rad(&self) -> [f64; WRIST_JOINTS] {
        [
            self.offsets_rad[2],
            self.offsets_rad[3],
            self.offsets_rad[4],
            self.offsets_rad[5],
        ]
    }

    /// Sets the paper robot's joint-2 direction (`s2` of docs/method.md).
    pub fn with_j2_direction(mut self, s2: i8) -> Self {
        self.arm.joints[1].axis = if s2 < 0 {
            JointAxis::NegX
        } else {
            JointAxis::X
        };
        self
    }

    /// The true joint angles of a commanded pose (rad).
    pub fn true_joints(&self, commanded_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        core::array::from_fn(|k| commanded_rad[k] + self.offsets_rad[k])
    }

    /// Where the joints really are for a commanded pose reached with `approach`: the
    /// zero offsets, then sag, backlash and repeatability.
    pub fn reached_joints(
        &self,
        commanded_rad: &[f64; JOINTS],
        approach: &[i8; JOINTS],
        rng: &mut ChaCha8Rng,
    ) -> [f64; JOINTS] {
        self.errors
            .deflect(&self.arm, &self.true_joints(commanded_rad), approach, rng)
    }

    /// Orientation of the flange pendant for commanded θ1..θ6 (rad), rigid and exact.
    pub fn flange_orientation(&self, commanded_rad: &[f64; JOINTS]) -> Rotation3<f64> {
        self.arm
            .flange_sensor(&self.base_tilt, &self.true_joints(commanded_rad))
    }

    /// Orientation of the upper-arm pendant with joints 1 and 2 commanded to `j1_rad`,
    /// `j2_rad`.
    pub fn upper_arm_orientation(&self, j1_rad: f64, j2_rad: f64) -> Rotation3<f64> {
        self.arm.upper_arm_sensor(
            &self.base_tilt,
            j1_rad + self.offsets_rad[0],
            j2_rad + self.offsets_rad[1],
        )
    }
}
