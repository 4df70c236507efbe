//! Specs a hostile user might write that are accepted must give a module that compiles and
//! computes exactly: type names that shadow the prelude (`Option`, `Vec`, `Some`, `Ok`, ...),
//! generated item names of other kinds (`BASIS`, `METRIC`), and a metric of decimals.

mod hostile {
    ga_macros::algebra! {
        basis = [e1, e2, e3];
        diagonal = [0.1, 0.3, 0.7];
        type Option { blades = [e1, e2, e3] }
        type Vec { blades = [e12, e13, e23] }
        type Result { blades = [s, e12, e13, e23], versor = true, unit = true }
        type Box { blades = [e123] }
        type String { blades = [s] }
        type Default { blades = [e1] }
        type Clone { blades = [e2] }
        type Copy { blades = [e3] }
        type Debug { blades = [e12] }
        type PartialEq { blades = [e13] }
        type Multivector { blades = [e23] }
        type Algebra { blades = [s, e1] }
        type Some { blades = [s, e2] }
        type None { blades = [s, e3] }
        type Ok { blades = [s, e123] }
        type Err { blades = [e1, e123] }
        type Sized { blades = [e2, e123] }
        type From { blades = [e1, e2] }
        type Output { blades = [e1, e23] }
        type BASIS { blades = [e2, e13] }
        type METRIC { blades = [e3, e12] }
        sandwich Result(Option);
    }
}

#[test]
fn prelude_names_compile_and_decimal_metrics_are_exact() {
    use hostile::*;
    let t = Box { e123: 1.0 };
    // <e123 ~e123> = 0.1 * 0.3 * 0.7, written as the decimal 0.021.
    assert_eq!(t.norm_squared(), 0.021);
    let v = Option {
        e1: 1.0,
        e2: 2.0,
        e3: 3.0,
    };
    // Each square is the metric entry as written.
    for (axis, square) in [
        ([1.0, 0.0, 0.0], 0.1),
        ([0.0, 1.0, 0.0], 0.3),
        ([0.0, 0.0, 1.0], 0.7),
    ] {
        let [e1, e2, e3] = axis;
        assert_eq!(Option { e1, e2, e3 }.norm_squared(), square);
    }
    let one = Result {
        s: 1.0,
        ..::core::default::Default::default()
    };
    // The identity rotor leaves a vector as it is.
    let moved = one.sandwich(v);
    assert_eq!((moved.e1, moved.e2, moved.e3), (v.e1, v.e2, v.e3));
    assert_eq!(METRIC[1][1], 0.3);
}
