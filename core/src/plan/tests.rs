//! The planner's unit tests: feasibility, determinism, refusals naming parameters.
use super::design::{better, prior_information, Inverse};
use super::*;
use crate::error::ParamSet;
use crate::model::{BaseTilt, SensorModel, Tilt};

fn pool64() -> std::vec::Vec<Candidate<f64>> {
    std::vec![Candidate::default(); DEFAULT_POOL]
}

#[test]
fn prng_is_deterministic_and_uniform() {
    let mut a = Xorshift64Star::new(7);
    let mut b = Xorshift64Star::new(7);
    let mut c = Xorshift64Star::new(8);
    let (mut sum, n) = (0.0, 10_000);
    for _ in 0..n {
        let x = a.unit_f64();
        assert_eq!(x, b.unit_f64());
        assert!((0.0..1.0).contains(&x));
        sum += x;
    }
    assert_ne!(a.next_u64(), c.next_u64());
    // Mean of 10,000 U(0,1): σ = 1/√(12·10⁴) ≈ 0.0029; 0.015 is 5σ.
    assert!((sum / n as f64 - 0.5).abs() < 0.015);
    // Seed 0 does not stall.
    let mut z = Xorshift64Star::new(0);
    assert_ne!(z.next_u64(), z.next_u64());
}

#[test]
fn default_plan_is_feasible_and_accurate() {
    let model = Stage2Model::<f64>::default();
    let config = PlanConfig::default();
    let p = plan(&model, &config, &mut pool64()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.poses_rad.len(), 8);
    let limit = config.window_rad - config.margin_rad;
    for q in &p.poses_rad {
        let t = model.predict(q, &[0.0; 4]);
        assert!(t.x_rad.abs() <= limit && t.y_rad.abs() <= limit, "{t:?}");
        for (qk, (lo, hi)) in q.iter().zip(config.limits_rad) {
            assert!((lo..=hi).contains(qk));
        }
    }
    let s = p.predicted_sigma_deg();
    // docs/method.md: 30 random poses in ±30° give 0.0025°; the brief asks 8 planned
    // ones to be at least 5× better, 0.0005°.
    assert!(s.iter().all(|&x| x > 0.0 && x < 0.0005), "{s:?}");
    // Joints free over a full turn: the design is near orthogonal (JᵀJ ∝ I).
    assert!(p.condition_number < 1.5, "{}", p.condition_number);
}

#[test]
fn exchange_never_worsens_the_greedy_design() {
    let model = Stage2Model::<f64>::default();
    let config = PlanConfig::default();
    let mut pool = pool64();
    let layout = config.extras.layout();
    let (found, _) = draw_pool(&model, &config, &layout, &mut pool);
    let pool = &pool[..found];
    let base = prior_information(&config.extras, config.noise_sigma_rad);
    let zeros = crate::stage2::zeros_map(&model, &layout);
    let score = |criterion, design: &[u16]| {
        Inverse::of(&information_of(pool, design, &base), &zeros).map(|i| i.score(criterion))
    };
    for criterion in [Criterion::AOptimal, Criterion::DOptimal] {
        let mut design = greedy(pool, 8, &base, &zeros);
        let before = score(criterion, &design);
        exchange(pool, &mut design, criterion, 20, &base, &zeros);
        let after = score(criterion, &design);
        assert!(
            !better(before, after),
            "{criterion:?}: {before:?} -> {after:?}"
        );
        let mut sorted = design.clone();
        sorted.sort_unstable();
        assert!(sorted.windows(2).all(|w| w[0] != w[1]), "distinct poses");
    }
}

#[test]
fn same_seed_same_plan_other_seed_other_plan() {
    let model = Stage2Model::<f64>::default();
    let config = PlanConfig::default();
    let a = plan(&model, &config, &mut pool64());
    let b = plan(&model, &config, &mut pool64());
    assert_eq!(a, b);
    let c = plan(&model, &PlanConfig { seed: 2, ..config }, &mut pool64());
    assert_ne!(a.map(|p| p.poses_rad), c.map(|p| p.poses_rad));
}

#[test]
fn pinned_joint_4_is_refused_naming_j3_and_j5() {
    // θ4 ≡ 0: Rx(θ3)·Rx(θ5) is one rotation, Δθ3 and Δθ5 cannot be told apart.
    let model = Stage2Model::<f64>::default();
    let mut config = PlanConfig::default();
    config.limits_rad[1] = (0.0, 0.0);
    let r = plan(&model, &config, &mut pool64());
    match r {
        Err(PlanError::Unobservable(FitError::RankDeficient { params })) => {
            assert_eq!(params, ParamSet::default().with(0).with(2), "{params}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn nearly_pinned_joint_4_is_ill_conditioned() {
    // θ4 within ±0.05°: separable in principle, not in practice.
    let model = Stage2Model::<f64>::default();
    let mut config = PlanConfig::default();
    config.limits_rad[1] = (-deg_to_rad(0.05), deg_to_rad(0.05));
    match plan(&model, &config, &mut pool64()) {
        Err(PlanError::Unobservable(FitError::IllConditioned { params, .. })) => {
            assert!(params.contains(0) && params.contains(2), "{params}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_settings_are_named() {
    let model = Stage2Model::<f64>::default();
    let base = PlanConfig::<f64>::default();
    let cases: [(PlanConfig<f64>, PlanError); 6] = [
        (
            PlanConfig { poses: 3, ..base },
            PlanError::TooFewPoses { got: 3, min: 4 },
        ),
        (
            PlanConfig {
                poses: MAX_POSES + 1,
                ..base
            },
            PlanError::TooManyPoses {
                got: MAX_POSES + 1,
                max: MAX_POSES,
            },
        ),
        (
            PlanConfig {
                margin_rad: base.window_rad,
                ..base
            },
            PlanError::InvalidSetting(PlanSetting::Margin),
        ),
        (
            PlanConfig {
                window_rad: f64::NAN,
                ..base
            },
            PlanError::InvalidSetting(PlanSetting::Window),
        ),
        (
            PlanConfig {
                limits_rad: [(0.0, 0.1), (0.0, 0.1), (0.2, 0.1), (0.0, 0.1)],
                ..base
            },
            PlanError::InvalidSetting(PlanSetting::Limits { joint: 5 }),
        ),
        (
            PlanConfig {
                candidates: 300,
                ..base
            },
            PlanError::PoolTooSmall {
                pool: 256,
                needed: 300,
            },
        ),
    ];
    for (config, expected) in cases {
        assert_eq!(plan(&model, &config, &mut pool64()), Err(expected));
    }
    let msg = std::format!(
        "{}",
        PlanError::InvalidSetting(PlanSetting::Limits { joint: 5 })
    );
    assert!(msg.contains("joint 5"), "{msg}");
}

#[test]
fn unreachable_window_is_reported() {
    // θ3 in [40°, 50°] with the other joints near 0 reads x ≈ 45°: never in ±9°.
    let model = Stage2Model::<f64>::default();
    let config = PlanConfig {
        limits_rad: limits_from_deg([(40.0, 50.0), (-5.0, 5.0), (-5.0, 5.0), (-5.0, 5.0)]),
        max_draws: 5_000,
        ..PlanConfig::default()
    };
    assert!(matches!(
        plan(&model, &config, &mut pool64()),
        Err(PlanError::WindowUnreachable {
            found: 0,
            draws: 5_000
        })
    ));
}

#[test]
fn plans_for_a_tilted_base_and_biased_sensor_stay_in_the_window() {
    let model = Stage2Model {
        base_tilt: BaseTilt::from_deg(0.5, -0.4),
        sensor: SensorModel::new(crate::model::Convention::Axis, Tilt::from_deg(0.05, -0.03)),
        ..Stage2Model::default()
    };
    let config = PlanConfig::default();
    let p = plan(&model, &config, &mut pool64()).unwrap_or_else(|e| panic!("{e}"));
    assert!(p.max_reading_rad <= config.window_rad - config.margin_rad);
}

#[test]
fn f32_plan_on_the_pendant_matches_f64_quality() {
    let model = Stage2Model::<f32>::default();
    let config = PlanConfig::<f32>::default();
    let mut pool = std::vec![Candidate::<f32>::default(); DEFAULT_POOL];
    let p = plan(&model, &config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
    let p64 = plan(
        &Stage2Model::default(),
        &PlanConfig::default(),
        &mut pool64(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    // Same seed, same candidates up to f32 rounding; the exchange may settle on a
    // slightly different set, so compare quality, not poses: within 20 %.
    for k in 0..4 {
        let r = f64::from(p.predicted_sigma_rad[k]) / p64.predicted_sigma_rad[k];
        assert!((0.8..1.25).contains(&r), "j{}: {r}", k + 3);
    }
}
