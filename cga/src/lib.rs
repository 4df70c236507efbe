//! Conformal geometric algebra G(4,1), generated at build time from `algebras/cga.toml`.
