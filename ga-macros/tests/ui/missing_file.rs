mod g3 {
    ga_macros::algebra!(path = "algebras/no_such_spec.toml");
}

fn main() {}
