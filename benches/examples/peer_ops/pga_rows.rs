//! The PGA rows of the harness: klein's operations on the PGA of `algebras/pga3d.toml`
//! generated in f32 (graded against klein) and in f64 (the same operations on the same inputs,
//! reported beside klein's f32 with no target).

use crate::{each1, each2, time_pass, typed, Record, N};
use std::collections::BTreeMap;
use std::hint::black_box;

/// PGA f64, the twin of the f32 module in `main.rs`.
mod pga64 {
    ga_macros::algebra!(path = "../algebras/pga3d.toml", scalar = f64);
}

/// One function timing every PGA row on the generated module `$m` of scalar `$s`, recording
/// them under keys `$prefix.*`.
macro_rules! pga_rows {
    ($name:ident, $m:path, $s:ty, $prefix:literal) => {
        #[allow(clippy::unnecessary_cast)]
        pub(crate) fn $name(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
            use $m::{Exp as _, Line, Log as _, Motor, Point, Rotor, Sandwich as _};
            fn cast<const K: usize>(a: [f64; K]) -> [$s; K] {
                a.map(|x| x as $s)
            }
            fn wide<const K: usize>(a: [$s; K]) -> [f64; K] {
                a.map(f64::from)
            }
            let ma = typed(&inp["pga.motor_a"], |a| Motor::from_array(cast(a)));
            let mb = typed(&inp["pga.motor_b"], |a| Motor::from_array(cast(a)));
            let pts = typed(&inp["pga.point"], |a| Point::from_array(cast(a)));
            let ra = typed(&inp["pga.rotor_a"], |a| Rotor::from_array(cast(a)));
            let rb = typed(&inp["pga.rotor_b"], |a| Rotor::from_array(cast(a)));
            let lines = typed(&inp["pga.line"], |a| Line::from_array(cast(a)));

            let mut out = vec![Point::new(0.0, 0.0, 0.0, 0.0); N];
            let ns = time_pass(&mut out, |o| {
                let (m, p) = black_box((&ma, &pts));
                each2(o, m, p, |m, p| m.sandwich(p));
            });
            rec.add(concat!($prefix, ".motor_point"), ns, &out, |p| {
                wide(p.to_array())
            });

            let ns = time_pass(&mut out, |o| {
                let (m, p) = black_box((&ma[0], &pts));
                let pm = m.point_matrix();
                for (o, p) in o.iter_mut().zip(p) {
                    *o = pm.apply(*p);
                }
            });
            rec.add(concat!($prefix, ".batch"), ns, &out, |p| wide(p.to_array()));

            let ns = time_pass(&mut out, |o| {
                let (m, p) = black_box((&ma[0], &pts));
                for (o, p) in o.iter_mut().zip(p) {
                    *o = m.sandwich(*p);
                }
            });
            rec.add(concat!($prefix, ".batch_sandwich"), ns, &out, |p| {
                wide(p.to_array())
            });

            let mut out = vec![Motor::from_array([0.0; 8]); N];
            let ns = time_pass(&mut out, |o| {
                let (a, b) = black_box((&ma, &mb));
                each2(o, a, b, |a, b| a * b);
            });
            rec.add(concat!($prefix, ".motor_motor"), ns, &out, |m| {
                wide(m.to_array())
            });

            let mut rout = vec![Rotor::from_array([0.0; 4]); N];
            let ns = time_pass(&mut rout, |o| {
                let (a, b) = black_box((&ra, &rb));
                each2(o, a, b, |a, b| a * b);
            });
            rec.add(concat!($prefix, ".rotor_rotor"), ns, &rout, |r| {
                wide(r.to_array())
            });

            let ns = time_pass(&mut out, |o| {
                let l = black_box(&lines);
                each1(o, l, |x| x.exp());
            });
            rec.add(concat!($prefix, ".exp"), ns, &out, |m| wide(m.to_array()));

            let mut lout = vec![Line::from_array([0.0; 6]); N];
            let ns = time_pass(&mut lout, |o| {
                let m = black_box(&ma);
                each1(o, m, |x| x.log());
            });
            rec.add(concat!($prefix, ".log"), ns, &lout, |l| wide(l.to_array()));

            let mut mats =
                vec![Motor::from_array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]).point_matrix(); N];
            let ns = time_pass(&mut mats, |o| {
                let m = black_box(&ma);
                each1(o, m, |x| x.point_matrix());
            });
            // The 4 x 4 block acting on (e032, e013, e021, e123), row-major (column 4 is the constant
            // column, zero for points).
            rec.add(
                concat!($prefix, ".motor_matrix"),
                ns,
                &mats,
                |pm| -> [f64; 16] {
                    let m = pm.rows();
                    std::array::from_fn(|k| f64::from(m[k / 4][k % 4]))
                },
            );
        }
    };
}

pga_rows!(pga_rows, crate::pga, f32, "pga");
pga_rows!(pga64_rows, pga64, f64, "pga64");
