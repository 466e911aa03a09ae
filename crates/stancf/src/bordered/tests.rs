use super::lu::{dense_lu, dense_solve};
use super::*;
use crate::band::SingularMatrix;
use crate::linear::Factorization;

fn shape(size: usize, kl: usize, ku: usize, border: &[usize]) -> BlockShape {
    BlockShape {
        size,
        kl,
        ku,
        border: border.to_vec(),
    }
}

/// Three blocks with overlapping borders of 7 points.
fn three_blocks() -> Vec<BlockShape> {
    vec![
        shape(17, 2, 3, &[0, 1, 2]),
        shape(9, 1, 1, &[2, 3, 4, 5]),
        shape(23, 4, 2, &[5, 6]),
    ]
}

/// A tiny LCG (Knuth's MMIX constants): values in [-1, 1).
fn lcg(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Global unknown -> (block, local index), `None` on the border; worked
/// out from the shapes alone, independently of the implementation.
fn owner(shapes: &[BlockShape], mut i: usize) -> Option<(usize, usize)> {
    for (b, s) in shapes.iter().enumerate() {
        if i < s.size {
            return Some((b, i));
        }
        i -= s.size;
    }
    None
}

fn in_structure(shapes: &[BlockShape], nb: usize, i: usize, j: usize) -> bool {
    let bs: usize = shapes.iter().map(|s| s.size).sum();
    assert!(i < bs + nb && j < bs + nb);
    match (owner(shapes, i), owner(shapes, j)) {
        (Some((a, li)), Some((b, lj))) => {
            let s = &shapes[a];
            a == b && li + s.ku >= lj && lj + s.kl >= li
        }
        (Some((a, _)), None) => shapes[a].border.contains(&(j - bs)),
        (None, Some((b, _))) => shapes[b].border.contains(&(i - bs)),
        (None, None) => true,
    }
}

/// The test matrix, dense: pseudo-random entries in the structure,
/// the diagonal above the sum of its row's other magnitudes (strictly
/// diagonally dominant, so every block and S are nonsingular).
fn dense_matrix(shapes: &[BlockShape], nb: usize, seed: u64) -> Vec<Vec<f64>> {
    let size = shapes.iter().map(|s| s.size).sum::<usize>() + nb;
    let mut state = seed;
    let mut a = vec![vec![0.0; size]; size];
    for (i, row) in a.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            if in_structure(shapes, nb, i, j) {
                *v = lcg(&mut state);
            }
        }
        let off: f64 = row.iter().map(|v| v.abs()).sum::<f64>() - row[i].abs();
        row[i] = 1.0 + off + row[i].abs();
    }
    a
}

fn fill_global(m: &mut BorderedMatrix, a: &[Vec<f64>]) {
    for (i, row) in a.iter().enumerate() {
        for (j, &v) in row.iter().enumerate() {
            if v != 0.0 {
                m.add(i, j, v);
            }
        }
    }
}

/// Fills the blocks' entries through `add_local` and D through `add`.
fn fill_local(m: &mut BorderedMatrix, shapes: &[BlockShape], a: &[Vec<f64>]) {
    let bs = m.border_start();
    for (b, s) in shapes.iter().enumerate() {
        let global = |l: usize| {
            if l < s.size {
                m.block_start(b) + l
            } else {
                bs + s.border[l - s.size]
            }
        };
        let nl = s.size + s.border.len();
        let mut entries = Vec::new();
        for li in 0..nl {
            for lj in 0..nl {
                let (i, j) = (global(li), global(lj));
                if (i < bs || j < bs) && a[i][j] != 0.0 {
                    entries.push((li, lj, a[i][j]));
                }
            }
        }
        for (li, lj, v) in entries {
            m.add_local(b, li, lj, v);
        }
    }
    for i in bs..a.len() {
        for j in bs..a.len() {
            m.add(i, j, a[i][j]);
        }
    }
}

fn dense_of(m: &BorderedMatrix) -> Vec<Vec<f64>> {
    let n = m.size();
    (0..n)
        .map(|i| (0..n).map(|j| m.get(i, j)).collect())
        .collect()
}

fn assert_close(x: &[f64], reference: &[f64], tol: f64, what: &str) {
    let scale = reference.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    for (i, (a, b)) in x.iter().zip(reference).enumerate() {
        assert!(
            (a - b).abs() <= tol * scale,
            "{what}: x[{i}] = {a}, expected {b}"
        );
    }
}

/// Fills `lu` from `a`, checks `get` and `mul_vec` against the dense
/// matrix, then solves A x = b against x_true and a dense LU.
fn solve_and_check(lu: &mut BorderedLu, a: &[Vec<f64>], seed: u64) {
    let n = a.len();
    lu.matrix_mut().clear();
    fill_global(lu.matrix_mut(), a);
    assert_eq!(dense_of(lu.matrix()), a);
    let mut state = seed;
    let x_true: Vec<f64> = (0..n).map(|_| lcg(&mut state)).collect();
    let mut b = vec![0.0; n];
    lu.matrix().mul_vec(&x_true, &mut b);
    let b_dense: Vec<f64> = a.iter().map(|row| dot(row, &x_true)).collect();
    assert_close(&b, &b_dense, 1e-14, "mul_vec");
    // The whole matrix by the dense LU.
    let mut full: Vec<f64> = a.iter().flatten().copied().collect();
    let mut pivots = vec![0; n];
    dense_lu(&mut full, n, &mut pivots).unwrap();
    let mut x_dense = b.clone();
    dense_solve(&full, n, &pivots, &mut x_dense);
    lu.factorize().unwrap();
    let mut x = b;
    lu.solve(&mut x);
    assert_close(&x, &x_true, 1e-12, "block elimination vs x_true");
    assert_close(&x, &x_dense, 1e-12, "block elimination vs dense LU");
}

#[test]
fn block_elimination_solves_like_a_dense_lu() {
    let shapes = three_blocks();
    let mut lu = BorderedLu::new(&shapes, 7);
    assert_eq!(lu.matrix().size(), 17 + 9 + 23 + 7);
    assert_eq!(lu.matrix().border_start(), 49);
    assert_eq!(lu.matrix().block_start(2), 26);
    for seed in [1u64, 2] {
        let a = dense_matrix(&shapes, 7, seed);
        solve_and_check(&mut lu, &a, seed + 10);
    }
}

#[test]
fn a_border_without_blocks_and_blocks_without_border_work() {
    // No border: independent band LUs.
    let shapes = vec![shape(6, 1, 2, &[]), shape(11, 3, 0, &[])];
    let mut lu = BorderedLu::new(&shapes, 0);
    solve_and_check(&mut lu, &dense_matrix(&shapes, 0, 3), 4);
    // One block with a border of 3; border index 1 only in D.
    let shapes = vec![shape(8, 2, 2, &[0, 2])];
    let mut lu = BorderedLu::new(&shapes, 3);
    solve_and_check(&mut lu, &dense_matrix(&shapes, 3, 5), 6);
    // A block without border next to one with.
    let shapes = vec![shape(5, 1, 1, &[0, 1, 2]), shape(4, 0, 3, &[])];
    let mut lu = BorderedLu::new(&shapes, 3);
    solve_and_check(&mut lu, &dense_matrix(&shapes, 3, 7), 8);
}

#[test]
fn pivoting_is_needed_and_done() {
    // A = [0 1 0; 1 0 1; 0 1 2] (det -2), B = C^T = e_0 e_0^T, and
    // D chosen so that S = D - C A^-1 B = [0 2; 3 1].
    let shapes = vec![shape(3, 1, 1, &[0, 1])];
    let mut lu = BorderedLu::new(&shapes, 2);
    let m = lu.matrix_mut();
    for (i, j, v) in [
        (0, 1, 1.0),
        (1, 0, 1.0),
        (1, 2, 1.0),
        (2, 1, 1.0),
        (2, 2, 2.0),
    ] {
        m.add(i, j, v);
    }
    m.add(0, 3, 1.0);
    m.add(3, 0, 1.0);
    // A^-1 e_0 = (1/2, 1, -1/2), so S_00 = D_00 - 1/2 = 0.
    m.add(3, 3, 0.5);
    m.add(3, 4, 2.0);
    m.add(4, 3, 3.0);
    m.add(4, 4, 1.0);
    let x_true = [1.0, -2.0, 3.0, 0.5, -1.5];
    let mut b = [0.0; 5];
    lu.matrix().mul_vec(&x_true, &mut b);
    lu.factorize().unwrap();
    assert_eq!(lu.matrix().d[0], 3.0, "S's rows were swapped");
    assert_eq!(lu.pivots, [1, 1]);
    lu.solve(&mut b);
    assert_close(&b, &x_true, 1e-15, "pivoted solve");
}

#[test]
fn a_singular_border_is_reported() {
    // A = B = C = I (2 x 2), D = I + [1 2; 2 4]: S = [1 2; 2 4], rank 1.
    let shapes = vec![shape(2, 0, 0, &[0, 1])];
    let mut lu = BorderedLu::new(&shapes, 2);
    let m = lu.matrix_mut();
    for k in 0..2 {
        m.add(k, k, 1.0);
        m.add(k, 2 + k, 1.0);
        m.add(2 + k, k, 1.0);
        m.add(2 + k, 2 + k, 1.0);
    }
    m.add(2, 2, 1.0);
    m.add(2, 3, 2.0);
    m.add(3, 2, 2.0);
    m.add(3, 3, 4.0);
    let err = lu.factorize().unwrap_err();
    assert!(err.column >= lu.matrix().border_start());
    assert_eq!(err, SingularMatrix { column: 3 });
    // A singular block reports its global column: block 1 (unknowns
    // 3..7) has an empty third column, global 5.
    let shapes = vec![shape(3, 1, 1, &[0]), shape(4, 1, 1, &[0])];
    let mut lu = BorderedLu::new(&shapes, 1);
    let m = lu.matrix_mut();
    for i in [0, 1, 2, 3, 4, 6, 7] {
        m.add(i, i, 1.0);
    }
    assert_eq!(lu.factorize(), Err(SingularMatrix { column: 5 }));
}

#[test]
fn add_local_and_add_agree() {
    let shapes = three_blocks();
    let a = dense_matrix(&shapes, 7, 9);
    let mut global = BorderedMatrix::new(&shapes, 7);
    let mut local = BorderedMatrix::new(&shapes, 7);
    fill_global(&mut global, &a);
    fill_local(&mut local, &shapes, &a);
    assert_eq!(dense_of(&global), a);
    assert_eq!(dense_of(&local), a);
    assert_eq!(global.max_abs(), local.max_abs());
    let mut copy = BorderedMatrix::new(&shapes, 7);
    copy.copy_from(&local);
    assert_eq!(dense_of(&copy), a);
}

#[test]
#[should_panic(expected = "outside the bordered structure")]
fn an_entry_coupling_two_blocks_is_refused() {
    let shapes = three_blocks();
    let mut m = BorderedMatrix::new(&shapes, 7);
    m.add(16, 17, 1.0);
}

#[test]
#[should_panic(expected = "not sorted and distinct")]
fn an_unsorted_border_is_refused() {
    BorderedMatrix::new(&[shape(3, 1, 1, &[2, 1])], 3);
}

/// No allocator hook in unit tests: the buffers' addresses and
/// capacities must not change through factorize and solve.
#[test]
fn factorize_and_solve_do_not_allocate() {
    fn buffers(lu: &BorderedLu) -> Vec<(usize, usize)> {
        let m = &lu.m;
        let mut v = vec![
            (m.d.as_ptr() as usize, m.d.capacity()),
            (m.block_of.as_ptr() as usize, m.block_of.capacity()),
            (lu.pivots.as_ptr() as usize, lu.pivots.capacity()),
        ];
        for blk in &m.blocks {
            v.push((blk.b.as_ptr() as usize, blk.b.capacity()));
            v.push((blk.c.as_ptr() as usize, blk.c.capacity()));
            v.push((blk.border.as_ptr() as usize, blk.border.capacity()));
        }
        v
    }
    let shapes = three_blocks();
    let mut lu = BorderedLu::new(&shapes, 7);
    fill_global(lu.matrix_mut(), &dense_matrix(&shapes, 7, 11));
    let before = buffers(&lu);
    lu.factorize().unwrap();
    let mut b = vec![1.0; lu.matrix().size()];
    lu.solve(&mut b);
    assert_eq!(buffers(&lu), before);
}

/// Blocks that touch the border only at their last rows or only at their
/// first rows (a line's end at a free point), with entries that are not
/// diagonally dominant, so the band LUs pivot: the forward and row
/// substitutions that start at the first nonzero row must solve as a
/// dense LU does.
#[test]
fn borders_at_a_blocks_end_or_start_solve_like_a_dense_lu_with_pivoting() {
    let shapes = vec![shape(30, 3, 2, &[0, 1, 2]), shape(25, 2, 4, &[1, 2, 3])];
    let nb = 4;
    for (seed, at_end) in [(3u64, true), (4, false), (5, true), (6, false)] {
        let size = 30 + 25 + nb;
        let bs = 55;
        let mut state = seed;
        let mut a = vec![vec![0.0; size]; size];
        for i in 0..size {
            for j in 0..size {
                if !in_structure(&shapes, nb, i, j) {
                    continue;
                }
                // Border couplings only within 4 rows of the block's end
                // (or start).
                let near = |k: usize| match owner(&shapes, k) {
                    Some((b, l)) => {
                        let n = shapes[b].size;
                        if at_end {
                            l + 4 >= n
                        } else {
                            l < 4
                        }
                    }
                    None => true,
                };
                if (i >= bs || j >= bs) && !(near(i) && near(j)) {
                    continue;
                }
                a[i][j] = lcg(&mut state);
            }
        }
        let mut lu = BorderedLu::new(&shapes, nb);
        solve_and_check(&mut lu, &a, seed + 20);
    }
}

/// A row operation on the border, a cleared row and a cleared column give
/// the matrix the dense operations give.
#[test]
fn border_row_operations_act_on_every_block_and_the_corner() {
    let shapes = three_blocks();
    let nb = 7;
    let n: usize = shapes.iter().map(|s| s.size).sum::<usize>() + nb;
    let mut a = dense_matrix(&shapes, nb, 7);
    // Every block touching a border row touches the others it is added
    // to: use rows the blocks share, or whose blocks are a superset.
    let bs = n - nb;
    let mut m = BorderedMatrix::new(&shapes, nb);
    fill_global(&mut m, &a);
    let (to, from) = (bs + shapes[0].border[0], bs + shapes[0].border[1]);
    let shares = shapes
        .iter()
        .all(|s| !s.border.contains(&(from - bs)) || s.border.contains(&(to - bs)));
    assert!(shares, "the test's rows must be shared");
    m.add_border_row(to, from, 0.75);
    m.clear_border_row(from);
    m.clear_border_column(to);
    for j in 0..n {
        let v = a[from][j];
        a[to][j] += 0.75 * v;
        a[from][j] = 0.0;
    }
    for row in a.iter_mut() {
        row[to] = 0.0;
    }
    let got = dense_of(&m);
    for i in 0..n {
        for j in 0..n {
            assert!((got[i][j] - a[i][j]).abs() < 1e-15, "({i}, {j})");
        }
    }
}
