mod big {
    ga_macros::algebra! {
        basis = [e1, e2, e3];
        diagonal = [1, 1e30, 1e30];
        type Vector { blades = [e1, e2, e3] }
    }
}

mod prefix {
    ga_macros::algebra! {
        basis = [e1, e2, e12];
        diagonal = [1, 1, 1];
    }
}

mod reserved {
    ga_macros::algebra! {
        basis = [e1, e2];
        diagonal = [1, 1];
        type V { blades = [e1, e2] }
        type R { blades = [s, e12], versor = true }
        type RVMatrix { blades = [e12] }
        sandwich R(V);
    }
}

fn main() {}
