//! Stage 2's unit tests: the analytic Jacobian against central differences for every
//! parameter, and exact recovery from noiseless data.

use super::*;
use crate::model::{
    rotation_from_rpy_deg, Arm, BaseTilt, Convention, Gain, JointAxis, Placement, SensorModel,
};
use crate::testing::isclose;
use nalgebra::Vector3;

/// An arm with fixed rotations, a non-paper axis and lengths, so no shortcut of the
/// paper's geometry can hide a slip.
fn arm() -> Arm<f64> {
    let mut arm = Arm::paper();
    arm.joints[1].origin = Placement {
        rotation: rotation_from_rpy_deg(0.0, 0.0, 15.0),
        translation_m: Vector3::new(0.02, 0.0, 0.4),
    };
    arm.joints[2].origin.translation_m = Vector3::new(0.45, 0.0, 0.0);
    arm.joints[3].origin = Placement {
        rotation: rotation_from_rpy_deg(0.0, 0.0, 30.0),
        translation_m: Vector3::new(0.0, 0.0, 0.035),
    };
    arm.joints[4].axis = JointAxis::NegZ;
    arm.joints[4].origin.translation_m = Vector3::new(0.42, 0.0, 0.0);
    arm.flange.translation_m = Vector3::new(0.08, 0.0, 0.0);
    arm
}

fn model(conv: Convention) -> Stage2Model<f64> {
    let arm = arm();
    Stage2Model {
        arm,
        base_tilt: BaseTilt::from_deg(0.3, -0.5),
        delta_theta2_rad: 0.004,
        stage1_j2_rad: -1.2,
        sensor: SensorModel {
            convention: conv,
            bias: Tilt::from_deg(0.01, -0.02),
            gain: Gain {
                xx: 0.002,
                yy: -0.001,
                xy: 0.003,
                yx: -0.002,
                xz: 0.004,
                yz: -0.003,
                zx: 0.002,
                zy: -0.004,
                zz: 0.003,
            },
        },
        reference_temperature_c: 20.0,
        drift_per_k: Tilt::from_deg(0.004, -0.003),
        y_weight: 1.3,
        masses: Some(MassModel::uniform(&arm)),
    }
}

const ALL: Extras = Extras {
    held: [false; 4],
    gain: true,
    cross_z: true,
    sag: true,
    bias_x: true,
    bias_y: true,
    drift: true,
    tilt: (1 << TILT_SLOTS) - 1,
    wrist_sag: WRIST_SAG_ALL,
    sag2: true,
    lash: super::params::LASH_ALL,
    transmission: super::params::HARMONIC_ALL,
};

#[test]
fn analytic_jacobian_matches_central_differences() {
    for conv in [Convention::Rpy, Convention::Axis] {
        let m = model(conv);
        let layout = ALL.layout();
        let pose = PoseReading {
            joints_rad: [0.1, -0.7, 0.3, -0.2, 0.5, 1.1],
            reading: Tilt::default(),
            temperature_c: Some(23.5),
        };
        let mut x = [0.0; MAX_PARAMS];
        for (i, v) in x.iter_mut().enumerate().take(layout.len()) {
            *v = 1e-3 * (i as f64 + 1.0) * if i % 2 == 0 { 1.0 } else { -1.0 };
        }
        let at = |x: &[f64; MAX_PARAMS]| {
            let e = Estimate::from_slots(&layout, x);
            let pass = m.pass(&e, &layout);
            m.predict_rows(&pass, &layout, &e, &pose, true)
        };
        let p = at(&x);
        for slot in 0..layout.len() {
            let h = 1e-6;
            let (mut xp, mut xm) = (x, x);
            xp[slot] += h;
            xm[slot] -= h;
            let d = at(&xp).reading.minus(&at(&xm).reading);
            // Central differences are O(h²) ≈ 1e-12; rounding adds ε/h ≈ 1e-10. The y
            // row is weighted by the model's y_weight.
            for (axis, fd) in [d.x_rad, d.y_rad * m.y_weight].iter().enumerate() {
                let got = p.rows[axis][slot];
                assert!(
                    isclose(fd / (2.0 * h), got, 0.0, 1e-8),
                    "{conv:?} {} axis {axis}: {} vs {got}",
                    layout.params()[slot].name(),
                    fd / (2.0 * h)
                );
            }
        }
        // The hand-over parameters: α, β, Δθ2, bias x, bias y.
        for k in 0..HANDOVER_PARAMS {
            let h = 1e-6;
            let (mut mp, mut mm) = (m, m);
            match k {
                0 => {
                    mp.base_tilt.alpha_rad += h;
                    mm.base_tilt.alpha_rad -= h;
                }
                1 => {
                    mp.base_tilt.beta_rad += h;
                    mm.base_tilt.beta_rad -= h;
                }
                2 => {
                    mp.delta_theta2_rad += h;
                    mm.delta_theta2_rad -= h;
                }
                3 => {
                    mp.sensor.bias.x_rad += h;
                    mm.sensor.bias.x_rad -= h;
                }
                _ => {
                    mp.sensor.bias.y_rad += h;
                    mm.sensor.bias.y_rad -= h;
                }
            }
            let e = Estimate::from_slots(&layout, &x);
            let r = |m: &Stage2Model<f64>| {
                m.predict_rows(&m.pass(&e, &layout), &layout, &e, &pose, false)
                    .reading
            };
            let d = r(&mp).minus(&r(&mm));
            for (axis, fd) in [d.x_rad, d.y_rad * m.y_weight].iter().enumerate() {
                let got = p.handover_rows[axis][k];
                assert!(
                    isclose(fd / (2.0 * h), got, 0.0, 1e-8),
                    "{conv:?} hand-over {k} axis {axis}: {} vs {got}",
                    fd / (2.0 * h)
                );
            }
        }
    }
}

#[test]
fn the_gain_moves_readings_as_a_real_sensors_axes_do() {
    // A 1 % sensitivity error on x reads a 5° x tilt as ~5.05°: that is what the
    // gain term models, and what an ideal-sensor fit would blame on the joints.
    let mut m = model(Convention::Axis);
    m.sensor.bias = Tilt::default();
    m.sensor.gain = Gain::default();
    let tilted = crate::model::rot_x(5f64.to_radians());
    let ideal = m.sensor.reading(&tilted);
    m.sensor.gain.yy = 0.01;
    let scaled = m.sensor.reading(&tilted);
    // Pendant x reads the chip's y (model/sensor.rs): E_yy scales the x reading.
    assert!(
        isclose(scaled.x_rad / ideal.x_rad, 1.01, 2e-4, 0.0),
        "{scaled:?}"
    );
}

#[test]
fn sag_and_drift_need_what_they_model() {
    let mut m = model(Convention::Rpy);
    m.masses = None;
    let poses = [PoseReading {
        joints_rad: [0.0; 6],
        reading: Tilt::default(),
        temperature_c: None,
    }; 6];
    let config = FitConfig {
        extras: Extras {
            sag: true,
            ..Extras::NONE
        },
        ..FitConfig::default()
    };
    let e = fit(&m, &poses, &config).unwrap_err();
    assert!(format!("{e}").contains("sag"), "{e}");
    let config = FitConfig {
        extras: Extras {
            drift: true,
            ..Extras::NONE
        },
        ..FitConfig::default()
    };
    let e = fit(&model(Convention::Rpy), &poses, &config).unwrap_err();
    assert!(format!("{e}").contains("drift_x+drift_y"), "{e}");
}

mod properties {
    //! Invariants of the fit on noiseless data from the model itself.
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Whatever the offsets (to ±10°), tilt, bias and well-spread poses, noiseless
        /// readings are fitted exactly, with zero residual, in either precision.
        #[test]
        fn noiseless_data_are_fitted_exactly(
            offsets in prop::array::uniform4(-0.17..0.17f64),
            alpha in -0.02..0.02f64, beta in -0.02..0.02f64,
            bias in (-0.002..0.002f64, -0.002..0.002f64),
            axis_conv in any::<bool>(),
            joints in prop::collection::vec(prop::array::uniform4(-0.6..0.6f64), 12),
        ) {
            let model = Stage2Model {
                base_tilt: BaseTilt { alpha_rad: alpha, beta_rad: beta },
                sensor: SensorModel::new(
                    if axis_conv { Convention::Axis } else { Convention::Rpy },
                    Tilt::new(bias.0, bias.1),
                ),
                ..Stage2Model::default()
            };
            let all: Vec<[f64; 6]> = joints.iter().map(|q| [0.0, 0.0, q[0], q[1], q[2], q[3]]).collect();
            let poses: Vec<PoseReading<f64>> = all
                .iter()
                .map(|q| PoseReading {
                    joints_rad: *q,
                    reading: model.predict(q, &offsets),
                    temperature_c: None,
                })
                .collect();
            // The range check has its own tests; here any reading goes.
            let config = FitConfig { sensor_range_rad: 4.0, ..FitConfig::default() };
            let bound = covariance_bound(&model, Extras::NONE, &all, &offsets, 1e-5);
            let r = fit(&model, &poses, &config);
            match bound {
                // Well separated at the truth (with room for the iteration's start at
                // zero): the fit must give the numbers, exactly.
                Ok(b) if b.condition_number < 300.0 => {
                    let r = r.map_err(|e| TestCaseError::fail(format!("{e}")))?;
                    for (found, truth) in r.offsets_rad.iter().zip(offsets) {
                        // The step tolerance is 1e-13 rad; rounding adds ~1e-15.
                        prop_assert!((found - truth).abs() < 1e-11, "{r:?}");
                    }
                    prop_assert!(r.residual_rms_rad < 1e-12);
                }
                // Weak sets may go either way, but never to wrong numbers.
                _ => {
                    if let Ok(r) = r {
                        for (found, truth) in r.offsets_rad.iter().zip(offsets) {
                            prop_assert!((found - truth).abs() < 1e-9, "{r:?}");
                        }
                    }
                }
            }
        }
    }
}

/// θ4 held at 0 (and no Δθ4) makes joints 3 and 5 coaxial: their zeros are one
/// parameter, refused by name; holding Δθ5 gives their sum in Δθ3, exactly on noiseless
/// data.
#[test]
fn a_held_offset_hands_its_twin_the_sum() {
    let model = Stage2Model::<f64> {
        sensor: SensorModel::new(Convention::Rpy, Tilt::default()),
        ..Stage2Model::default()
    };
    let truth = [0.004, 0.0, 0.002, 0.005];
    let mut poses = std::vec::Vec::new();
    for i in 0..12 {
        let a = f64::from(i) * 0.5;
        let q = [
            0.0,
            0.0,
            0.1 * a.sin(),
            0.0,
            0.12 * (1.3 * a).cos(),
            0.15 * (0.7 * a + 1.0).sin(),
        ];
        let mut t = q;
        for k in 0..4 {
            t[k + 2] += truth[k];
        }
        let reading = model
            .sensor
            .reading(&model.arm.flange_sensor(&model.base_tilt, &t));
        poses.push(PoseReading {
            joints_rad: q,
            reading,
            temperature_c: None,
        });
    }
    let config = FitConfig::<f64> {
        min_residual_dof: 100,
        ..FitConfig::default()
    };
    match fit(&model, &poses, &config) {
        Err(FitError::RankDeficient { params }) => {
            assert!(params.contains(0) && params.contains(2), "{params}");
        }
        other => panic!("{other:?}"),
    }
    let held = FitConfig {
        extras: Extras {
            held: [false, false, true, false],
            ..Extras::NONE
        },
        ..config
    };
    let r = fit(&model, &poses, &held).unwrap();
    // Noiseless: rounding only (1e-12 rad).
    assert!(
        isclose(r.offsets_rad[0], truth[0] + truth[2], 0.0, 1e-12),
        "{:?}",
        r.offsets_rad
    );
    assert!(isclose(r.offsets_rad[2], 0.0, 0.0, 1e-12));
    assert!(isclose(r.offsets_rad[1], truth[1], 0.0, 1e-12));
    assert!(isclose(r.offsets_rad[3], truth[3], 0.0, 1e-12));
}

/// The priors' share of the zeros' variance: none where no term carries a prior; with
/// the reducers' harmonics fitted, a part of each variance, and nearly all of Δθ2's
/// correction (joint 2's error at its stage-1 angle, which ±0.6 rad of swing around it
/// leaves to its stated size), never more than the variance itself.
#[test]
fn the_priors_share_of_the_zeros_variance_is_part_of_it() {
    let model = Stage2Model::<f64> {
        sensor: SensorModel::new(Convention::Rpy, Tilt::default()),
        ..Stage2Model::default()
    };
    let poses: std::vec::Vec<PoseReading<f64>> = (0..40)
        .map(|i| {
            let a = f64::from(i);
            let q = [
                0.0,
                0.6 * (0.9 * a).sin(),
                0.6 * (1.7 * a + 0.3).sin(),
                1.2 * (0.5 * a + 1.0).cos(),
                0.5 * (2.3 * a).sin(),
                1.5 * (0.31 * a + 2.0).sin(),
            ];
            PoseReading {
                joints_rad: q,
                reading: model.predict(&q, &[0.0; 4]),
                temperature_c: None,
            }
        })
        .collect();
    // σ is the sensor's stated noise: the readings here have none. The range check
    // has its own tests; here any reading goes.
    let config = FitConfig::<f64> {
        min_residual_dof: 1000,
        sensor_range_rad: 4.0,
        ..FitConfig::default()
    };
    let plain = fit(&model, &poses, &config).unwrap();
    assert_eq!(plain.zeros_prior_variance_rad2, [0.0; ZEROS]);
    let reducers = FitConfig {
        extras: Extras {
            transmission: super::params::HARMONIC_ALL,
            ..Extras::NONE
        },
        ..config
    };
    let r = fit(&model, &poses, &reducers).unwrap();
    for (k, p) in r.zeros_prior_variance_rad2.iter().enumerate() {
        let v = r.zeros_covariance_rad2[k][k];
        assert!(*p > 0.0 && *p < v, "zero {k}: prior part {p} of {v}");
    }
    let share = r.zeros_prior_variance_rad2[0] / r.zeros_covariance_rad2[0][0];
    assert!(share > 0.5, "Δθ2's correction: prior share {share}");
}
