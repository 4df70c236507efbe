//! criterion: the generated closed-form exp/log of G(4,1) (`cga::Exp`, `cga::Log`, emitted by
//! ga-codegen, issue 26) against the hand-written ones of `cga` (`Bivector::exp_motor`,
//! `Motor::log`, `ScaledMotor::exp`, `ScaledMotor::log`), f64, over 64 generators each.
//!
//! `cargo bench -p benches --bench exp_log -- --quick`

use cga::f64::{EvenVersor, Exp, Log};
use cga::{Bivector, Motor, ScaledMotor};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn generators(dilate: bool) -> Vec<Bivector> {
    (0..64)
        .map(|i| {
            let a = f64::from(i) * 0.37;
            let mut b = Bivector::default();
            (b.e12, b.e13, b.e23) = (0.8 * a.sin(), 0.6 * a.cos(), 0.3 + 0.01 * a);
            (b.e1i, b.e2i, b.e3i) = (a.cos(), 2.0 * a.sin(), 0.5 - 0.1 * a);
            if dilate {
                b.eoi = 0.2 * (a * 1.3).sin();
            }
            b
        })
        .collect()
}

fn exp_log(c: &mut Criterion) {
    let bs = generators(false);
    let ms: Vec<Motor> = bs.iter().map(|b| b.exp_motor()).collect();
    let mut g = c.benchmark_group("exp_log");
    g.bench_function("motor exp hand-written", |b| {
        b.iter(|| bs.iter().map(|x| black_box(*x).exp_motor().s).sum::<f64>())
    });
    g.bench_function("motor exp generated", |b| {
        b.iter(|| {
            bs.iter()
                .map(|x| Exp::<Motor>::exp(black_box(*x)).s)
                .sum::<f64>()
        })
    });
    g.bench_function("motor log hand-written", |b| {
        b.iter(|| ms.iter().map(|m| black_box(*m).log().e12).sum::<f64>())
    });
    g.bench_function("motor log generated", |b| {
        b.iter(|| ms.iter().map(|m| Log::log(black_box(*m)).e12).sum::<f64>())
    });
    g.bench_function("motor normalize+log generated", |b| {
        b.iter(|| {
            ms.iter()
                .map(|m| Log::log(EvenVersor::normalize(black_box(*m))).e12)
                .sum::<f64>()
        })
    });
    let bs = generators(true);
    let ss: Vec<ScaledMotor> = bs.iter().map(|b| ScaledMotor::exp(*b)).collect();
    g.bench_function("scaled exp hand-written", |b| {
        b.iter(|| {
            bs.iter()
                .map(|x| ScaledMotor::exp(black_box(*x)).s)
                .sum::<f64>()
        })
    });
    g.bench_function("scaled exp generated", |b| {
        b.iter(|| {
            bs.iter()
                .map(|x| Exp::<ScaledMotor>::exp(black_box(*x)).s)
                .sum::<f64>()
        })
    });
    g.bench_function("scaled log hand-written", |b| {
        b.iter(|| ss.iter().map(|m| black_box(*m).log().e12).sum::<f64>())
    });
    g.bench_function("scaled log generated", |b| {
        b.iter(|| ss.iter().map(|m| Log::log(black_box(*m)).e12).sum::<f64>())
    });
    g.finish();
}

criterion_group!(benches, exp_log);
criterion_main!(benches);
