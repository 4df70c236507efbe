mod g3 {
    ga_macros::algebra! {
        basis = [e1, e2, e3];
        diagonal = [1, 1, 1];
        type Vector { blades = [e1, e2, e3] }
        type Planar { blades = [e1, e2] }
        type Rotor { blades = [s, e12, e13, e23], versor = true, unit = true }
        sandwich Rotor(Vector) -> Planar;
    }
}

fn main() {}
