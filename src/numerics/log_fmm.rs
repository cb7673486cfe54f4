//! The line contact's deformation product in linear time: the influence matrix of the
//! logarithmic kernel, K_{ij} = ∫_{cell j} ln|xᵢ − s| ds ([`line_log_cell`]), applied by a
//! one-dimensional black-box fast multipole method (Fong & Darve 2009, "The black-box fast
//! multipole method", J. Comput. Phys. 228: Chebyshev interpolation of the kernel in both
//! variables), with the entries of nearby cells exact. It stands where the dense matrix would
//! cost n² entries to build and n² multiply–adds per product.
//!
//! - **Clusters.** Index ranges of the cells, each bisected at the middle of its extent (the
//!   grids are clustered, so a cluster's extent, not its count, sets what is well separated),
//!   down to at most [`LEAF`] cells. A cluster's extent runs from its first cell's left face
//!   to its last cell's right face; its points (the nodes, one in each cell) lie inside.
//! - **Well separated.** Two clusters whose gap is at least the wider one's extent. For x in
//!   one and s in the other, ln|x − s| ≈ Σ_l Σ_m L_l(x) ln|ξ_l − ζ_m| L_m(s), with ξ and ζ the
//!   [`ORDER`] Chebyshev points of the two extents and L their Lagrange polynomials. The
//!   interpolation error falls as ρ^−ORDER with ρ = 3 + √8 (the Bernstein ellipse that just
//!   avoids the other cluster), 2e−11 at worst; against the dense product the error is 2e−13
//!   of Σ|K_ij v_j| (tested).
//! - **A product** y = K v: the moments q_σ,m = Σ_j v_j ∫_{cell j} L_m(s) ds, up the tree
//!   (a parent's polynomial is exactly its children's interpolant of it); the interactions
//!   g_τ += ln|ξ − ζ| q_σ of every well-separated pair; the local expansions down the tree to
//!   the points; the near pairs' exact entries. About (3·LEAF + 2·ORDER + 10·ORDER²/LEAF)
//!   multiply–adds per point.

use std::f64::consts::PI;
use std::ops::Range;

use super::half_space::{line_log_cell, line_log_cells};
use super::quadrature::gauss_legendre;

/// Most cells in a leaf cluster. Near work per point grows as 3·LEAF, far work as 1/LEAF.
const LEAF: usize = 32;
/// Chebyshev points per cluster.
const ORDER: usize = 14;

/// K_{ij} for `points` (one in each cell) and the cells between consecutive `faces`, in
/// O(n) storage and O(n) per product.
#[derive(Debug, Clone)]
pub struct LineLogInfluence {
    points: Vec<f64>,
    faces: Vec<f64>,
    clusters: Vec<Cluster>,
    /// Well-separated pairs (target cluster, source cluster): the ORDER × ORDER matrix
    /// ln|ξ_l − ζ_m|, row-major.
    far: Vec<(usize, usize, Vec<f64>)>,
    /// Pairs of leaves too close to interpolate: their exact entries, row-major.
    near: Vec<(usize, usize, Vec<f64>)>,
}

#[derive(Debug, Clone)]
struct Cluster {
    /// Cells lo..hi.
    lo: usize,
    hi: usize,
    /// Its extent [faces[lo], faces[hi]].
    left: f64,
    right: f64,
    shape: Shape,
    /// Whether a product needs its moments (it or an ancestor is the source of a far pair)
    /// and its local expansion (it or an ancestor is the target of one): on a small grid most
    /// clusters need neither.
    moments: bool,
    locals: bool,
}

#[derive(Debug, Clone)]
enum Shape {
    /// The two halves, each with its points' values of this cluster's Lagrange polynomials,
    /// ORDER × ORDER row-major: [m′][m] = L_m(ξ^child_m′).
    Parent([(usize, Vec<f64>); 2]),
    /// Per cell (row-major, cells × ORDER): ∫_{cell j} L_m(s) ds, and L_m(x_j) at its point.
    Leaf { moments: Vec<f64>, values: Vec<f64> },
}

impl LineLogInfluence {
    /// The operator for `points[j]` inside the cell [`faces[j]`, `faces[j + 1]`] (faces
    /// increasing).
    #[must_use]
    pub fn new(points: &[f64], faces: &[f64]) -> Self {
        assert_eq!(points.len() + 1, faces.len(), "one point per cell");
        let mut operator = LineLogInfluence {
            points: points.to_vec(),
            faces: faces.to_vec(),
            clusters: Vec::new(),
            far: Vec::new(),
            near: Vec::new(),
        };
        let root = operator.cluster(0, points.len());
        operator.pair(root, root);
        for (target, source, _) in &operator.far {
            operator.clusters[*target].locals = true;
            operator.clusters[*source].moments = true;
        }
        // Parents come before their children.
        for c in 0..operator.clusters.len() {
            if let Shape::Parent([(a, _), (b, _)]) = operator.clusters[c].shape {
                let (moments, locals) = (operator.clusters[c].moments, operator.clusters[c].locals);
                for child in [a, b] {
                    operator.clusters[child].moments |= moments;
                    operator.clusters[child].locals |= locals;
                }
            }
        }
        operator
    }

    /// K_{ij}, exact.
    #[must_use]
    pub fn entry(&self, i: usize, j: usize) -> f64 {
        line_log_cell(self.points[i], self.faces[j], self.faces[j + 1])
    }

    /// The entries it keeps exact (the near pairs'): rows, columns, the block row-major.
    pub fn exact_blocks(&self) -> impl Iterator<Item = (Range<usize>, Range<usize>, &[f64])> {
        self.near.iter().map(|(target, source, block)| {
            let (t, s) = (&self.clusters[*target], &self.clusters[*source]);
            (t.lo..t.hi, s.lo..s.hi, block.as_slice())
        })
    }

    /// y = K v.
    #[must_use]
    pub fn apply(&self, v: &[f64]) -> Vec<f64> {
        let count = self.clusters.len();
        let mut moments = vec![0.0; count * ORDER];
        // Children come after their parents (built depth first), so a reverse pass is upward.
        for (c, cluster) in self.clusters.iter().enumerate().rev() {
            if !cluster.moments {
                continue;
            }
            let (head, tail) = moments.split_at_mut((c + 1) * ORDER);
            let q = &mut head[c * ORDER..];
            match &cluster.shape {
                Shape::Leaf { moments: m, .. } => {
                    for (row, &vj) in m.chunks_exact(ORDER).zip(&v[cluster.lo..cluster.hi]) {
                        q.iter_mut().zip(row).for_each(|(q, w)| *q += w * vj);
                    }
                }
                Shape::Parent(children) => {
                    for (child, transfer) in children {
                        let offset = (child - c - 1) * ORDER;
                        let qc = &tail[offset..offset + ORDER];
                        for (row, &qm) in transfer.chunks_exact(ORDER).zip(qc) {
                            q.iter_mut().zip(row).for_each(|(q, t)| *q += t * qm);
                        }
                    }
                }
            }
        }
        let mut locals = vec![0.0; count * ORDER];
        for (target, source, m2l) in &self.far {
            let q = &moments[source * ORDER..(source + 1) * ORDER];
            let g = &mut locals[target * ORDER..(target + 1) * ORDER];
            for (g, row) in g.iter_mut().zip(m2l.chunks_exact(ORDER)) {
                *g += super::dense::dot(row, q);
            }
        }
        let mut out = vec![0.0; self.points.len()];
        for (c, cluster) in self.clusters.iter().enumerate() {
            if !cluster.locals {
                continue;
            }
            let (head, tail) = locals.split_at_mut((c + 1) * ORDER);
            let g = &head[c * ORDER..];
            match &cluster.shape {
                Shape::Leaf { values, .. } => {
                    for (y, row) in out[cluster.lo..cluster.hi]
                        .iter_mut()
                        .zip(values.chunks_exact(ORDER))
                    {
                        *y += super::dense::dot(row, g);
                    }
                }
                Shape::Parent(children) => {
                    for (child, transfer) in children {
                        let offset = (child - c - 1) * ORDER;
                        let gc = &mut tail[offset..offset + ORDER];
                        for (gc, row) in gc.iter_mut().zip(transfer.chunks_exact(ORDER)) {
                            *gc += super::dense::dot(row, g);
                        }
                    }
                }
            }
        }
        for (target, source, block) in &self.near {
            let (t, s) = (&self.clusters[*target], &self.clusters[*source]);
            let vs = &v[s.lo..s.hi];
            for (y, row) in out[t.lo..t.hi]
                .iter_mut()
                .zip(block.chunks_exact(s.hi - s.lo))
            {
                *y += super::dense::dot(row, vs);
            }
        }
        out
    }

    /// Builds the cluster of cells lo..hi and its descendants (depth first); returns its index.
    fn cluster(&mut self, lo: usize, hi: usize) -> usize {
        let (left, right) = (self.faces[lo], self.faces[hi]);
        let index = self.clusters.len();
        self.clusters.push(Cluster {
            lo,
            hi,
            left,
            right,
            shape: Shape::Parent(Default::default()),
            moments: false,
            locals: false,
        });
        let shape = if hi - lo <= LEAF {
            self.leaf(lo, hi, left, right)
        } else {
            // The first cell whose centre is past the middle of the extent, leaving at least
            // one cell on each side.
            let middle = 0.5 * (left + right);
            let split = (lo + 1..hi)
                .find(|&j| 0.5 * (self.faces[j] + self.faces[j + 1]) > middle)
                .unwrap_or(hi - 1);
            let own = Chebyshev::on(left, right);
            let children = [(lo, split), (split, hi)].map(|(a, b)| {
                let child = self.cluster(a, b);
                let c = &self.clusters[child];
                let transfer = Chebyshev::on(c.left, c.right)
                    .nodes
                    .iter()
                    .flat_map(|&x| own.lagrange(x))
                    .collect();
                (child, transfer)
            });
            Shape::Parent(children)
        };
        self.clusters[index].shape = shape;
        index
    }

    /// A leaf's moments (Gauss–Legendre, exact for the polynomials) and point values.
    fn leaf(&self, lo: usize, hi: usize, left: f64, right: f64) -> Shape {
        let own = Chebyshev::on(left, right);
        let rule = gauss_legendre(ORDER.div_ceil(2));
        let mut moments = Vec::with_capacity((hi - lo) * ORDER);
        let mut values = Vec::with_capacity((hi - lo) * ORDER);
        for j in lo..hi {
            let (a, b) = (self.faces[j], self.faces[j + 1]);
            let mut integral = [0.0; ORDER];
            for &(t, w) in &rule {
                let s = 0.5 * (a + b) + 0.5 * (b - a) * t;
                for (m, l) in integral.iter_mut().zip(own.lagrange(s)) {
                    *m += 0.5 * (b - a) * w * l;
                }
            }
            moments.extend_from_slice(&integral);
            values.extend(own.lagrange(self.points[j]));
        }
        Shape::Leaf { moments, values }
    }

    /// Sorts the pair (target, source) into far and near blocks, splitting the wider cluster
    /// until the pair is well separated or both are leaves.
    fn pair(&mut self, target: usize, source: usize) {
        let (t, s) = (&self.clusters[target], &self.clusters[source]);
        let gap = (s.left - t.right).max(t.left - s.right);
        let (t_width, s_width) = (t.right - t.left, s.right - s.left);
        let children = |c: &Cluster| match &c.shape {
            Shape::Parent([(a, _), (b, _)]) => Some([*a, *b]),
            Shape::Leaf { .. } => None,
        };
        // A positive gap: clusters of zero width (repeated faces) stay near and exact.
        if gap > 0.0 && gap >= t_width.max(s_width) {
            let (xi, zeta) = (
                Chebyshev::on(t.left, t.right),
                Chebyshev::on(s.left, s.right),
            );
            let m2l = xi
                .nodes
                .iter()
                .flat_map(|x| zeta.nodes.iter().map(move |z| (x - z).abs().ln()))
                .collect();
            self.far.push((target, source, m2l));
            return;
        }
        match (children(t), children(s)) {
            (None, None) => {
                let faces = &self.faces[s.lo..=s.hi];
                let block = self.points[t.lo..t.hi]
                    .iter()
                    .flat_map(|&x| line_log_cells(x, faces))
                    .collect();
                self.near.push((target, source, block));
            }
            (Some(tc), Some(_)) if t_width >= s_width => {
                tc.into_iter().for_each(|c| self.pair(c, source));
            }
            (Some(tc), None) => tc.into_iter().for_each(|c| self.pair(c, source)),
            (_, Some(sc)) => sc.into_iter().for_each(|c| self.pair(target, c)),
        }
    }
}

/// The ORDER Chebyshev points (first kind) of [left, right], with their barycentric weights
/// (−1)^l sin((2l + 1)π/2n) (Berrut & Trefethen 2004).
#[derive(Debug, Clone, Copy)]
struct Chebyshev {
    nodes: [f64; ORDER],
    weights: [f64; ORDER],
}

impl Chebyshev {
    fn on(left: f64, right: f64) -> Self {
        let (centre, half) = (0.5 * (left + right), 0.5 * (right - left));
        let angle = |l: usize| (2 * l + 1) as f64 * PI / (2 * ORDER) as f64;
        Chebyshev {
            nodes: std::array::from_fn(|l| centre + half * angle(l).cos()),
            weights: std::array::from_fn(|l| {
                if l % 2 == 0 {
                    angle(l).sin()
                } else {
                    -angle(l).sin()
                }
            }),
        }
    }

    /// The Lagrange polynomials of the nodes at x, by the barycentric formula.
    fn lagrange(&self, x: f64) -> [f64; ORDER] {
        if let Some(hit) = self.nodes.iter().position(|&n| n == x) {
            return std::array::from_fn(|l| if l == hit { 1.0 } else { 0.0 });
        }
        let terms: [f64; ORDER] = std::array::from_fn(|l| self.weights[l] / (x - self.nodes[l]));
        let sum: f64 = terms.iter().sum();
        terms.map(|t| t / sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points one per cell on a grid clustered as the line EHL's: dense at two places.
    fn clustered(cells: usize) -> (Vec<f64>, Vec<f64>) {
        // From −4.5 to 1.5, the spacing falling 25-fold at −1 and at 1.
        let stretch = |u: f64| {
            let x = -4.5 + 6.0 * u;
            x - 0.96 * ((30.0 * (x + 1.0)).tanh() + (30.0 * (x - 1.0)).tanh()) / 30.0
        };
        let nodes: Vec<f64> = (0..=cells)
            .map(|i| stretch(i as f64 / cells as f64))
            .collect();
        let mut faces = vec![nodes[0]];
        faces.extend(nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])));
        faces.push(nodes[cells]);
        (nodes, faces)
    }

    #[test]
    fn the_product_matches_the_dense_matrix() {
        for cells in [20, 100, 257, 1000] {
            let (points, faces) = clustered(cells);
            assert!(points.windows(2).all(|w| w[1] > w[0]), "grid monotone");
            let operator = LineLogInfluence::new(&points, &faces);
            let n = points.len();
            // From a thousand cells on, most of the product is interpolated.
            let near: usize = operator.near.iter().map(|(_, _, b)| b.len()).sum();
            assert_eq!(
                near < n * n / 3,
                cells >= 1000,
                "{cells} cells: {near} near entries"
            );
            // A Hertz-like field with a spike, and an alternating one.
            for v in [
                points
                    .iter()
                    .map(|&x| (1.0 - x * x).max(0.0).sqrt())
                    .collect::<Vec<f64>>(),
                (0..n)
                    .map(|j| if j % 2 == 0 { 1.0 } else { -0.7 })
                    .collect(),
            ] {
                let fast = operator.apply(&v);
                let mut worst: f64 = 0.0;
                let mut scale: f64 = 0.0;
                for (i, y) in fast.iter().enumerate() {
                    let terms = v
                        .iter()
                        .enumerate()
                        .map(|(j, vj)| operator.entry(i, j) * vj);
                    let exact: f64 = terms.clone().sum();
                    worst = worst.max((y - exact).abs());
                    scale = scale.max(terms.map(f64::abs).sum());
                }
                assert!(
                    worst < 1e-12 * scale,
                    "{cells} cells: error {worst:e} of {scale}"
                );
            }
        }
    }

    #[test]
    fn exact_blocks_hold_exact_entries_and_every_neighbour() {
        let (points, faces) = clustered(1000);
        let operator = LineLogInfluence::new(&points, &faces);
        let n = points.len();
        let mut neighbours = vec![false; n];
        for (rows, columns, block) in operator.exact_blocks() {
            for (i, entries) in rows.zip(block.chunks_exact(columns.len())) {
                for (j, &k) in columns.clone().zip(entries) {
                    assert_eq!(k, operator.entry(i, j), "({i}, {j})");
                    if j == i + 1 {
                        neighbours[i] = true;
                    }
                }
            }
        }
        assert!(
            neighbours[..n - 1].iter().all(|&held| held),
            "a neighbour pair interpolated"
        );
    }

    #[test]
    fn far_work_stays_linear() {
        // Interactions and near entries per point do not grow with the grid.
        let per_point = |cells: usize| {
            let (points, faces) = clustered(cells);
            let operator = LineLogInfluence::new(&points, &faces);
            let near: usize = operator.near.iter().map(|(_, _, b)| b.len()).sum();
            let far = operator.far.len() * ORDER * ORDER;
            (near + far) as f64 / points.len() as f64
        };
        let (small, large) = (per_point(512), per_point(8192));
        assert!(
            large < 1.3 * small,
            "work per point {small} at 512, {large} at 8192"
        );
    }

    #[test]
    fn lagrange_polynomials_interpolate_a_polynomial_exactly() {
        let points = Chebyshev::on(-0.3, 2.0);
        // Degree ORDER − 1 = 13.
        let p = |x: f64| 1.0 - 2.0 * x + 0.5 * x.powi(7) - 0.01 * x.powi(13);
        for x in [-0.3, 0.1, 1.234, 2.0, points.nodes[3]] {
            let value: f64 = points
                .lagrange(x)
                .iter()
                .zip(&points.nodes)
                .map(|(l, &n)| l * p(n))
                .sum();
            assert!((value - p(x)).abs() < 1e-11 * p(x).abs().max(1.0), "{x}");
        }
    }
}
