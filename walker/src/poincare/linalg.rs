//! Hand-written small dense linear algebra of the Poincare map: the 8x8 matrix product.
//!
//! Self-contained (no imports) so that `walker/benches/linalg.rs` can compile this very file
//! and compare it with nalgebra.

/// An 8x8 matrix, row by row.
pub(crate) type M8 = [[f64; 8]; 8];

/// The product `a b` of two 8x8 matrices, each entry summed over `k` in ascending order.
pub(crate) fn matmul(a: &M8, b: &M8) -> M8 {
    let mut c = [[0.0; 8]; 8];
    for i in 0..8 {
        for j in 0..8 {
            c[i][j] = (0..8).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}
