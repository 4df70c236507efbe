//! Meshes, Laplacians, sparse solves, harmonic fields and the CGA mesh deformers.
