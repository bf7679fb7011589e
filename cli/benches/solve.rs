//! One 30-pose stage-2 solve on the paper's Table 4 setup, in f64 (desktop) and f32
//! (the pendant's precision, here on the host CPU); and one whole real-world session
//! on the KR 6 (stages 0-2 with the SCL3300's model: 48 captures, 18 parameters, the
//! second pass after stage 1 is solved again with the gains).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use zerocal_core::model::{Convention, Tilt};
use zerocal_core::stage2::{fit, FitConfig, PoseReading, Stage2Model};
use zerocal_sim::{PoseSampler, SimInclinometer, SimRobot, Table4};

fn table4_poses() -> Vec<PoseReading<f64>> {
    let robot = SimRobot::paper(Table4::OFFSETS_DEG, (0.0, 0.0));
    let mut sensor = SimInclinometer::new(Convention::Rpy, Tilt::default(), Table4::noise(), 42);
    let mut sampler = PoseSampler::symmetric(180.0, Table4::WINDOW_DEG, 42);
    match sampler.sample(&robot, &sensor, Table4::POSES) {
        Ok(joints) => joints
            .iter()
            .map(|q| PoseReading {
                joints_rad: *q,
                reading: sensor.read(&robot.flange_orientation(q)),
                temperature_c: None,
            })
            .collect(),
        Err(e) => panic!("bench setup: {e:?}"),
    }
}

fn bench(c: &mut Criterion) {
    let poses = table4_poses();
    let p32: Vec<PoseReading<f32>> = poses
        .iter()
        .map(|p| PoseReading {
            joints_rad: p.joints_rad.map(|q| q as f32),
            reading: Tilt::new(p.reading.x_rad as f32, p.reading.y_rad as f32),
            temperature_c: None,
        })
        .collect();
    let (m64, c64) = (Stage2Model::<f64>::default(), FitConfig::<f64>::default());
    let (m32, c32) = (Stage2Model::<f32>::default(), FitConfig::<f32>::default());
    c.bench_function("solve_30_poses_f64", |b| {
        b.iter(|| fit(black_box(&m64), black_box(&poses), &c64))
    });
    c.bench_function("solve_30_poses_f32", |b| {
        b.iter(|| fit(black_box(&m32), black_box(&p32), &c32))
    });

    let kr6 = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (plan, config) = zerocal_sim::montecarlo::setup(
        &kr6,
        zerocal_sim::montecarlo::Method::Compensated,
        zerocal_sim::montecarlo::DEFAULT_POSES,
    )
    .unwrap();
    let world = zerocal_sim::world::WorldConfig::real();
    let s = zerocal_sim::world::RealSession::simulate(&kr6, &plan, &world, 1);
    let readings = zerocal_core::session::SessionReadings {
        convention: Convention::Axis,
        arm: kr6.arm,
        masses: kr6.mass_model(),
        bias: zerocal_core::session::BiasSource::Reversal(s.stage0),
        stage1: s.stage1,
        poses: &s.poses,
        capture_index: None,
        temperatures: zerocal_core::session::StageTemperatures {
            stage0_c: Some(s.stage0_temperature_c),
            stage1_c: Some(s.stage1_temperature_c),
        },
        closing: Some(s.closing),
    };
    c.bench_function("session_kr6_real_f64", |b| {
        b.iter(|| zerocal_core::session::solve(black_box(&readings), &config))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
