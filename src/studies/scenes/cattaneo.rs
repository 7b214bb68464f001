//! Cattaneo–Mindlin in plane strain: the cylinder of the Hertz scene pressed
//! on a block by a normal load P, then sheared by a tangential load Q < μP
//! applied monotonically in steps, with Coulomb friction μ. Checked with
//! the frictional oracle ([`crate::studies::oracle::frictional`]), which
//! needs a conforming interface: unlike the Hertz scene, this one is a full
//! model (the tangential load breaks the symmetry) whose cylinder bottom
//! nodes sit at the x of the block's top nodes, over the whole width of the
//! cylinder part.
//!
//! **Geometry and mesh.** As in [`super::hertz`]: the block
//! [−2R, 2R] × [−2R, 0] (clamped at its bottom), and the part of the
//! cylinder (radius R) between its circular bottom y = R − √(R² − x²) and its
//! centre line y = R over |x| ≤ 0.8R. Structured meshes, element size h over
//! 1.5a on either side of the contact point, graded outwards, mirror-symmetric
//! about x = 0. The block's x positions are the cylinder's, continued
//! outwards with the same grading; the block's top is the lower contact side
//! over |x| ≤ 0.8R only ([`TAG_BLOCK_TOP`]), the cylinder's bottom the upper
//! one ([`TAG_CYLINDER`]): every pair is one block node under one cylinder
//! node, with the initial gap R − √(R² − x²).
//!
//! **Loading: a rigid platen, displacement-controlled.** The cylinder's
//! centre line ([`TAG_PLATEN`]) is given a uniform displacement
//! (δₜ, −δₙ): first δₙ (one step, δₜ = 0), then δₜ in steps, δₙ held. P and
//! Q are the resultants of the contact forces (= the platen's reactions).
//! Why not forces on the centre line: a tangential force at height R above
//! the contact has a moment QR about it, which a cylinder free to rotate
//! could only balance by shifting the pressure by QR/P ≈ 7a (Q/P = 0.15);
//! Cattaneo and Mindlin's bodies do not rotate, and the platen's vertical
//! reactions supply that moment. A prescribed δₜ also keeps the cylinder's
//! horizontal position determined when μ = 0. The solver finds δₙ so that
//! P is the load of the target half-width a, and each δₜ so that Q/(μP)
//! takes the requested values (secant iterations on one oracle step, from
//! the previous step's state: the history is that of the accepted steps).
//!
//! **Analytic solution** (Johnson, *Contact Mechanics*, §4.2 and §7.1;
//! plane strain). Hertz: a = √(4PR/(πE*)), p(x) = p₀√(1 − x²/a²),
//! p₀ = 2P/(πa), 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂. Cattaneo–Mindlin
//! under Q < μP: stick for |x| < c, c = a√(1 − Q/(μP)), slip for
//! c < |x| < a, and the shear traction
//! q(x) = μp₀[√(1 − x²/a²) − (c/a)√(1 − x²/c²)] for |x| < c,
//! q(x) = μp(x) for c ≤ |x| < a, 0 outside. Assumptions: half-spaces
//! (a ≪ R and the bodies' sizes), monotonic Q at constant P, one μ for
//! stick and slip, and **Dundurs' β = 0** (elastically similar bodies, or
//! materials chosen so): otherwise the shear changes the pressure and the
//! tangential problem is not this one ([`CattaneoMindlin::dundurs_beta`];
//! the analytic checks hold only for β = 0).
//!
//! **Measured.** q(x) positive along Q: the traction the cylinder exerts on
//! the block, −λₜ/length at a pair. a: the pressure p² extrapolated to zero
//! from the last two loaded nodes (as the Hertz scene); c: likewise the
//! stick margin (μp − |q|)², which is linear in x near c
//! (μp − |q| = μp₀(c/a)√(1 − x²/c²) inside c), from the last two stick nodes
//! counted from the centre; each on both sides, averaged.

use crate::contact::ContactOptions;
use crate::error::{Error, Result};
use crate::fem::element::Tempering;
use crate::fem::material::{Material, PlaneMode};
use crate::model::{Component, Model};
use crate::solve::report::ContactReport;
use crate::studies::meshgen::{Diagonal, MeshBuilder, graded};
use crate::studies::oracle::frictional::{
    FrictionalOracle, FrictionalStep, LoadCase, PairResult, PairState,
};

/// Tag of the block's supported (clamped) bottom.
pub const TAG_SUPPORT: i32 = 1;
/// Tag of the block's top edge under the cylinder (contact side a, lower).
pub const TAG_BLOCK_TOP: i32 = 2;
/// Tag of the cylinder's curved edge (contact side b, upper).
pub const TAG_CYLINDER: i32 = 3;
/// Tag of the cylinder's centre line, the rigid platen.
pub const TAG_PLATEN: i32 = 4;

/// Hertz half-width a = √(4PR/(πE*)) of a cylinder of radius R under the
/// line load P (per unit thickness).
pub fn hertz_half_width(p: f64, radius: f64, e_star: f64) -> f64 {
    (4.0 * p * radius / (std::f64::consts::PI * e_star)).sqrt()
}

/// Hertz pressure p₀√(1 − x²/a²) (0 for |x| ≥ a).
pub fn hertz_pressure(a: f64, p0: f64, x: f64) -> f64 {
    let t = 1.0 - (x / a) * (x / a);
    if t > 0.0 { p0 * t.sqrt() } else { 0.0 }
}

/// Stick half-width c = a√(1 − Q/(μP)) (`q_over_mu_p` = Q/(μP) in [0, 1]).
pub fn stick_half_width(a: f64, q_over_mu_p: f64) -> f64 {
    a * (1.0 - q_over_mu_p).max(0.0).sqrt()
}

/// The Cattaneo–Mindlin shear traction (plane strain, β = 0):
/// μp₀[√(1 − x²/a²) − (c/a)√(1 − x²/c²)] for |x| < c, μp₀√(1 − x²/a²) for
/// c ≤ |x| < a, 0 outside; positive along the tangential load.
pub fn cattaneo_mindlin(a: f64, c: f64, p0: f64, mu: f64, x: f64) -> f64 {
    let slip = mu * hertz_pressure(a, p0, x);
    if x.abs() < c {
        slip - mu * (c / a) * hertz_pressure(c, p0, x)
    } else {
        slip
    }
}

/// The Mindlin–Deresiewicz shear traction after unloading from Q* to
/// Q < Q* at constant P (Johnson, *Contact Mechanics*, §7.2; β = 0): the
/// loading's Cattaneo–Mindlin traction of stick half-width `c_star`, less
/// twice that of a load (Q* − Q)/2, of stick half-width `c_back` =
/// a√(1 − (Q* − Q)/(2μP)): reverse slip for c_back < |x| < a.
pub fn mindlin_deresiewicz(a: f64, c_star: f64, c_back: f64, p0: f64, mu: f64, x: f64) -> f64 {
    cattaneo_mindlin(a, c_star, p0, mu, x) - 2.0 * cattaneo_mindlin(a, c_back, p0, mu, x)
}

/// Parameters of the Cattaneo–Mindlin scene. [`Default`]: R = 1,
/// a = 0.005R, equal steel-like bodies (β = 0), μ = 0.3, h = a/16, the
/// normal load in one step.
///
/// Why a = 0.005R and not the Hertz scene's 0.02R: the finite cylinder is
/// not a half-space, and even at β = 0 its normal loading leaves an odd
/// shear traction of relative order a/R, which the tangential problem sees
/// against μp₀ (1/μ times larger than against p₀): at a = 0.02R the stick
/// zone is off-centre by 3 % of c (the two sides' c differ by that much at
/// every h), at 0.005R by 0.8 %.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CattaneoMindlin {
    /// Cylinder radius R.
    pub radius: f64,
    /// The Hertz half-width a the normal load is chosen for.
    pub half_width: f64,
    /// Young's modulus of the block (body 1).
    pub e_block: f64,
    /// Poisson ratio of the block.
    pub nu_block: f64,
    /// Young's modulus of the cylinder (body 2).
    pub e_cylinder: f64,
    /// Poisson ratio of the cylinder.
    pub nu_cylinder: f64,
    /// Coulomb friction coefficient.
    pub mu: f64,
    /// Element size at the contact (over 1.5a either side of x = 0).
    pub mesh_size: f64,
    /// Growth of the element size away from the contact region.
    pub grading: f64,
    /// Steps of the normal loading (equal increments of δₙ).
    pub normal_steps: usize,
}

impl Default for CattaneoMindlin {
    fn default() -> Self {
        CattaneoMindlin {
            radius: 1.0,
            half_width: 0.005,
            e_block: 2e11,
            nu_block: 0.3,
            e_cylinder: 2e11,
            nu_cylinder: 0.3,
            mu: 0.3,
            mesh_size: 0.005 / 16.0,
            grading: 1.15,
            normal_steps: 1,
        }
    }
}

/// The analytic Hertz / Cattaneo–Mindlin values for given P and Q.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Analytic {
    /// Contact half-width.
    pub a: f64,
    /// Peak pressure.
    pub p0: f64,
    /// Stick half-width.
    pub c: f64,
}

/// The built scene.
pub struct CattaneoScene {
    /// The model (platen and support prescribed, values 0; the contact pair
    /// (block top, cylinder) declared for TFEM).
    pub model: Model,
    /// The cylinder's centre-line nodes (the platen).
    pub platen: Vec<usize>,
    /// Nodes of the block (the first ones); the rest belong to the cylinder.
    pub n_block_nodes: usize,
    /// The target normal load P.
    pub load: f64,
}

/// One load step of the scene, measured against the analytic solution for
/// the step's measured P and Q.
#[derive(Debug, Clone)]
pub struct CattaneoStep {
    /// The platen's displacement (δₜ, −δₙ).
    pub platen: [f64; 2],
    /// The requested Q/(μP) (0 for the normal step).
    pub target: f64,
    /// The oracle's step.
    pub step: FrictionalStep,
    /// Oracle steps tried to hit the target (secant iterations).
    pub trials: usize,
    /// Measured normal load P = Σλₙ.
    pub p: f64,
    /// Measured tangential load Q = −Σλₜ (the force on the block, along +x).
    pub q: f64,
    /// The analytic a, p₀, c for P and Q.
    pub analytic: Analytic,
    /// Measured contact half-width (mean of both sides).
    pub a: f64,
    /// Measured stick half-width (mean of both sides).
    pub c: f64,
    /// Measured stick half-width on the side x < 0 and x > 0.
    pub c_sides: [f64; 2],
    /// Stick half-width from a least-squares fit of the stick nodes'
    /// deficit (μp − q)² = A − Bx² over |x| ≤ 0.8c (c = `c`): c = √(A/B).
    pub c_fit: f64,
    /// Nodal (x, p, q) of the pairs, sorted by x.
    pub traction: Vec<(f64, f64, f64)>,
    /// ‖q_h − q‖ / ‖q‖ (discrete L2 over the pairs, weighted by their
    /// lengths), q the analytic shear traction at the nodes.
    pub q_error_l2: f64,
    /// max |q_h − q| / (μp₀).
    pub q_error_max: f64,
    /// Nodes whose state differs from the analysis (stick |x| < c, slip
    /// c < |x| < a, open |x| > a) farther than one element from c and a.
    pub misclassified: usize,
    /// Wall time of the step, trials included.
    pub seconds: f64,
}

/// The scene's solution: the normal step, then the tangential steps.
#[derive(Debug, Clone)]
pub struct CattaneoSolution {
    /// Assembly and condensation time of the oracle.
    pub setup_seconds: f64,
    /// Number of node pairs.
    pub pairs: usize,
    /// Number of nodes.
    pub nodes: usize,
    /// The normal step (Q = 0).
    pub normal: CattaneoStep,
    /// The tangential steps, one per requested Q/(μP).
    pub tangential: Vec<CattaneoStep>,
}

/// `pos` (starting at 0) mirrored: −pos reversed, then pos.
fn mirrored(pos: &[f64]) -> Vec<f64> {
    pos.iter()
        .rev()
        .map(|x| -x)
        .chain(pos.iter().skip(1).copied())
        .collect()
}

/// Continues a graded subdivision to `b`, each spacing `ratio` times the
/// previous (as [`graded`] ends).
fn extend_graded(mut xs: Vec<f64>, b: f64, ratio: f64) -> Vec<f64> {
    let n = xs.len();
    let mut step = xs[n - 1] - xs[n - 2];
    let mut x = xs[n - 1];
    while x < b {
        step *= ratio;
        x += step;
        if x + 0.5 * step >= b {
            x = b;
        }
        xs.push(x.min(b));
    }
    xs.dedup();
    xs
}

impl CattaneoMindlin {
    /// E* of the pair.
    pub fn e_star(&self) -> f64 {
        1.0 / ((1.0 - self.nu_block * self.nu_block) / self.e_block
            + (1.0 - self.nu_cylinder * self.nu_cylinder) / self.e_cylinder)
    }

    /// Dundurs' β (plane strain) of the pair:
    /// [G₁(1 − 2ν₂) − G₂(1 − 2ν₁)] / [2G₁(1 − ν₂) + 2G₂(1 − ν₁)].
    /// The analytic solution assumes β = 0.
    pub fn dundurs_beta(&self) -> f64 {
        let g1 = self.e_block / (2.0 * (1.0 + self.nu_block));
        let g2 = self.e_cylinder / (2.0 * (1.0 + self.nu_cylinder));
        let (n1, n2) = (self.nu_block, self.nu_cylinder);
        (g1 * (1.0 - 2.0 * n2) - g2 * (1.0 - 2.0 * n1))
            / (2.0 * g1 * (1.0 - n2) + 2.0 * g2 * (1.0 - n1))
    }

    /// The line load P giving the half-width a: P = πa²E*/(4R).
    pub fn load(&self) -> f64 {
        std::f64::consts::PI * self.half_width * self.half_width * self.e_star()
            / (4.0 * self.radius)
    }

    /// The analytic a, p₀, c for the loads P, Q.
    pub fn analytic(&self, p: f64, q: f64) -> Analytic {
        let a = hertz_half_width(p, self.radius, self.e_star());
        Analytic {
            a,
            p0: 2.0 * p / (std::f64::consts::PI * a),
            c: if self.mu > 0.0 {
                stick_half_width(a, q / (self.mu * p))
            } else {
                0.0
            },
        }
    }

    /// Builds the mesh, materials, supports, platen and contact pair.
    pub fn build(&self) -> Result<CattaneoScene> {
        let (r, a, h) = (self.radius, self.half_width, self.mesh_size);
        if !(r > 0.0 && a > 0.0 && a < 0.3 * r && h > 0.0 && h <= a) {
            return Err(Error::argument(format!(
                "cattaneo: need R > 0, 0 < a < 0.3R and 0 < h <= a (got R = {r}, a = {a}, h = {h})"
            )));
        }
        if !(self.grading >= 1.0 && self.grading < 2.0 && self.mu >= 0.0) {
            return Err(Error::argument(format!(
                "cattaneo: need a grading in [1, 2) and μ >= 0 (got {}, {})",
                self.grading, self.mu
            )));
        }
        let fine = 1.5 * a;
        let w_cyl = 0.8 * r;
        let xs_cyl = graded(0.0, w_cyl, h, fine, self.grading)?;
        let xs_block = extend_graded(xs_cyl.clone(), 2.0 * r, self.grading);
        let (xs_cyl, xs_block) = (mirrored(&xs_cyl), mirrored(&xs_block));
        let depth: Vec<f64> = graded(0.0, 2.0 * r, h, fine, self.grading)?
            .into_iter()
            .rev()
            .map(|d| -d)
            .collect();
        let ts: Vec<f64> = graded(0.0, r, h, fine, self.grading)?
            .into_iter()
            .map(|y| y / r)
            .collect();
        let bottom = |x: f64| r - (r * r - x * x).sqrt();
        let mut b = MeshBuilder::new();
        let diagonal = Diagonal::MirroredAt(0.0);
        let block = b.add_grid(&xs_block, &depth, 1, diagonal);
        let n_block_nodes = b.nodes.len();
        let cylinder = b.add_mapped_grid(
            &xs_cyl,
            &ts,
            |x, t| [x, bottom(x) + t * (r - bottom(x))],
            2,
            diagonal,
        );
        let in_row = |row: &[usize], v: usize| row.binary_search(&v).is_ok();
        let (top, base) = (&block[block.len() - 1], &block[0]);
        let (curve, centre) = (&cylinder[0], &cylinder[cylinder.len() - 1]);
        let mut edges = Vec::new();
        let mut tags = Vec::new();
        for e in b.boundary_edges() {
            let both = |row: &[usize]| in_row(row, e[0]) && in_row(row, e[1]);
            let under = |v: usize| b.nodes[v][0].abs() <= w_cyl;
            let tag = if both(top) && under(e[0]) && under(e[1]) {
                TAG_BLOCK_TOP
            } else if both(base) {
                TAG_SUPPORT
            } else if both(centre) {
                TAG_PLATEN
            } else if both(curve) {
                TAG_CYLINDER
            } else {
                continue;
            };
            edges.push(e);
            tags.push(tag);
        }
        let platen = centre.clone();
        let mut model = Model::new();
        model.set_mesh(b.build()?);
        model.set_boundary_edges(&edges, &tags)?;
        let plane = PlaneMode::Strain;
        model.set_material(
            1,
            Material::new(self.e_block, self.nu_block, plane, "block")?,
        )?;
        model.set_material(
            2,
            Material::new(self.e_cylinder, self.nu_cylinder, plane, "cylinder")?,
        )?;
        model.set_tempering(Tempering::Auto)?;
        for tag in [TAG_SUPPORT, TAG_PLATEN] {
            model.fix_edges(tag, Component::X, 0.0)?;
            model.fix_edges(tag, Component::Y, 0.0)?;
        }
        model.add_contact_pair(TAG_BLOCK_TOP, TAG_CYLINDER)?;
        Ok(CattaneoScene {
            model,
            platen,
            n_block_nodes,
            load: self.load(),
        })
    }
}

/// Where f² (f ≥ 0, decreasing to 0 at the edge) reaches 0, extrapolated
/// linearly in |x| from the last two points with f > 0 of `pts` ((|x|, f)
/// sorted by |x|, the first ones with f > 0 contiguous).
fn extrapolate_edge(pts: &[(f64, f64)]) -> f64 {
    let last = pts.iter().position(|&(_, f)| f <= 0.0).unwrap_or(pts.len());
    if last < 2 {
        return f64::NAN;
    }
    let ((x1, f1), (x2, f2)) = (pts[last - 2], pts[last - 1]);
    x2 + f2 * f2 * (x2 - x1) / (f1 * f1 - f2 * f2)
}

impl CattaneoScene {
    /// The load case "platen displaced by (0, −1)".
    pub fn normal_case(&self) -> LoadCase {
        let mut c = LoadCase::zero(self.n_nodes());
        for &v in &self.platen {
            c.prescribed[2 * v + 1] = -1.0;
        }
        c
    }

    /// The load case "platen displaced by (1, 0)".
    pub fn tangential_case(&self) -> LoadCase {
        let mut c = LoadCase::zero(self.n_nodes());
        for &v in &self.platen {
            c.prescribed[2 * v] = 1.0;
        }
        c
    }

    fn n_nodes(&self) -> usize {
        self.model.mesh().map_or(0, |m| m.nodes().len())
    }

    /// The loads of the platen displacement (δₜ, −δₙ).
    pub fn platen_loads(&self, delta_t: f64, delta_n: f64) -> Result<LoadCase> {
        LoadCase::combination(
            &[self.normal_case(), self.tangential_case()],
            &[delta_n, delta_t],
        )
    }

    /// Solves with the frictional oracle: the normal step to the load P of
    /// the target a, then one tangential step per entry of `ratios`
    /// (increasing Q/(μP) in (0, 1)), each measured.
    pub fn solve(&self, cm: &CattaneoMindlin, ratios: &[f64]) -> Result<CattaneoSolution> {
        if ratios.iter().any(|r| !(*r > 0.0 && *r < 1.0)) || cm.mu <= 0.0 && !ratios.is_empty() {
            return Err(Error::argument(
                "cattaneo: the ratios Q/(μP) must lie in (0, 1), with μ > 0",
            ));
        }
        let oracle = FrictionalOracle::new(&self.model, TAG_BLOCK_TOP, TAG_CYLINDER)?;
        let tol = 1e-11;
        // Normal step: P(δₙ) = P by secant iterations.
        let t0 = std::time::Instant::now();
        let target = self.load;
        let p_of = |s: &FrictionalStep| s.contact_resultant()[0];
        let mut trials = 0;
        let ns = cm.normal_steps.max(1);
        let mut run = |dn: f64| -> Result<(f64, FrictionalStep)> {
            trials += 1;
            let mut s = oracle.step(cm.mu, None, &self.platen_loads(0.0, dn / ns as f64)?)?;
            for k in 2..=ns {
                let loads = self.platen_loads(0.0, dn * k as f64 / ns as f64)?;
                s = oracle.step(cm.mu, Some(&s), &loads)?;
            }
            Ok((p_of(&s) - target, s))
        };
        let d0 = target / cm.e_star();
        let (f0, _) = run(d0)?;
        let mut pts = vec![(0.0, -target), (d0, f0)];
        let (dn, normal) = loop {
            let ((x0, y0), (x1, y1)) = (pts[pts.len() - 2], pts[pts.len() - 1]);
            let x = x1 - y1 * (x1 - x0) / (y1 - y0);
            let (y, s) = run(x)?;
            if y.abs() <= tol * target {
                break (x, s);
            }
            if pts.len() > 60 {
                return Err(Error::new(
                    crate::error::Status::NotConverged,
                    "cattaneo: the normal load was not reached",
                ));
            }
            pts.push((x, y));
        };
        let normal = self.measure(cm, normal, [0.0, -dn], 0.0, trials, t0)?;
        // Tangential steps.
        let mut tangential: Vec<CattaneoStep> = Vec::new();
        let mut slope: Option<f64> = None;
        for &ratio in ratios {
            let t0 = std::time::Instant::now();
            let prev = tangential.last().unwrap_or(&normal);
            let dt_prev = prev.platen[0];
            let residual = |s: &FrictionalStep| {
                let [p, lt] = s.contact_resultant();
                -lt - ratio * cm.mu * p
            };
            let mut trials = 0;
            let mut run = |dt: f64| -> Result<(f64, FrictionalStep)> {
                trials += 1;
                let s = oracle.step(cm.mu, Some(&prev.step), &self.platen_loads(dt, dn)?)?;
                Ok((residual(&s), s))
            };
            let y_prev = residual(&prev.step);
            let guess = dt_prev - y_prev / slope.unwrap_or(cm.e_star());
            let (y0, _) = run(guess)?;
            let mut pts = vec![(dt_prev, y_prev), (guess, y0)];
            let (dt, step) = loop {
                let ((x0, y0), (x1, y1)) = (pts[pts.len() - 2], pts[pts.len() - 1]);
                let x = x1 - y1 * (x1 - x0) / (y1 - y0);
                let (y, s) = run(x)?;
                if y.abs() <= tol * cm.mu * target {
                    break (x, s);
                }
                if pts.len() > 60 {
                    return Err(Error::new(
                        crate::error::Status::NotConverged,
                        format!("cattaneo: Q/(μP) = {ratio} was not reached"),
                    ));
                }
                pts.push((x, y));
            };
            slope = Some(-y_prev / (dt - dt_prev));
            let m = self.measure(cm, step, [dt, -dn], ratio, trials, t0)?;
            tangential.push(m);
        }
        Ok(CattaneoSolution {
            setup_seconds: oracle.setup_seconds(),
            pairs: oracle.pairs().len(),
            nodes: self.n_nodes(),
            normal,
            tangential,
        })
    }

    /// Measures one step against the analytic solution for its P and Q.
    pub fn measure(
        &self,
        cm: &CattaneoMindlin,
        step: FrictionalStep,
        platen: [f64; 2],
        target: f64,
        trials: usize,
        t0: std::time::Instant,
    ) -> Result<CattaneoStep> {
        let [p, lt] = step.contact_resultant();
        let q = -lt;
        let analytic = cm.analytic(p, q);
        let mut pairs: Vec<_> = step.pairs.clone();
        pairs.sort_by(|a, b| a.x.total_cmp(&b.x));
        let traction: Vec<(f64, f64, f64)> = pairs
            .iter()
            .map(|r| (r.x, r.normal, -r.tangential))
            .collect();
        let centre = pairs
            .iter()
            .position(|r| r.x == 0.0)
            .ok_or_else(|| Error::state("cattaneo: no pair at x = 0"))?;
        let sides: [Vec<usize>; 2] = [
            (0..=centre).rev().collect(),
            (centre..pairs.len()).collect(),
        ];
        let mut a_sides = [0.0; 2];
        let mut c_sides = [0.0; 2];
        for (k, side) in sides.iter().enumerate() {
            let pressure: Vec<(f64, f64)> = side
                .iter()
                .map(|&i| (pairs[i].x.abs(), pairs[i].normal))
                .collect();
            a_sides[k] = extrapolate_edge(&pressure);
            let margin: Vec<(f64, f64)> = side
                .iter()
                .map(|&i| {
                    let r = &pairs[i];
                    let m = if r.state == PairState::Stick {
                        (cm.mu * r.normal - r.tangential.abs()).max(f64::MIN_POSITIVE)
                    } else {
                        0.0
                    };
                    (r.x.abs(), m)
                })
                .collect();
            c_sides[k] = if cm.mu == f64::INFINITY {
                a_sides[k]
            } else {
                extrapolate_edge(&margin)
            };
        }
        // (μp − q)² = μ²p₀²(c²/a²)(1 − x²/c²) inside c.
        let pts: Vec<(f64, f64)> = pairs
            .iter()
            .filter(|r| {
                r.state == PairState::Stick && r.x.abs() <= 0.8 * 0.5 * (c_sides[0] + c_sides[1])
            })
            .map(|r| (r.x * r.x, (cm.mu * r.normal + r.tangential).powi(2)))
            .collect();
        let c_fit = if pts.len() >= 3 && cm.mu.is_finite() {
            let n = pts.len() as f64;
            let (sx, sy) = pts.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
            let (mx, my) = (sx / n, sy / n);
            let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
            let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
            let slope = sxy / sxx;
            ((my - slope * mx) / -slope).sqrt()
        } else {
            f64::NAN
        };
        let q_exact: Vec<f64> = traction
            .iter()
            .map(|&(x, _, _)| cattaneo_mindlin(analytic.a, analytic.c, analytic.p0, cm.mu, x))
            .collect();
        let (mut num, mut den, mut max) = (0.0, 0.0, 0.0f64);
        for ((r, &(_, _, qh)), qe) in pairs.iter().zip(&traction).zip(&q_exact) {
            num += r.length * (qh - qe) * (qh - qe);
            den += r.length * qe * qe;
            max = max.max((qh - qe).abs());
        }
        let h = cm.mesh_size;
        let misclassified = pairs
            .iter()
            .filter(|r| {
                let x = r.x.abs();
                let (a, c) = (analytic.a, analytic.c);
                let expected = if x < c - h {
                    PairState::Stick
                } else if x > c + h && x < a - h {
                    PairState::Slip
                } else if x > a + h {
                    PairState::Open
                } else {
                    return false;
                };
                r.state != expected
            })
            .count();
        Ok(CattaneoStep {
            platen,
            target,
            trials,
            p,
            q,
            analytic,
            a: 0.5 * (a_sides[0] + a_sides[1]),
            c: 0.5 * (c_sides[0] + c_sides[1]),
            c_sides,
            c_fit,
            traction,
            q_error_l2: if den > 0.0 {
                (num / den).sqrt()
            } else {
                num.sqrt()
            },
            q_error_max: max / (cm.mu * analytic.p0),
            misclassified,
            seconds: t0.elapsed().as_secs_f64(),
            step,
        })
    }
}

/// The scene solved by TFEM's frictional contact elements (docs/method.md
/// §6.15) instead of the oracle: load steps of the model itself, the
/// platen moved by [`Model::set_prescribed`], secant iterations on whole
/// steps (each trial reverted), measured like the oracle's steps from the
/// nodal contact forces of each block/cylinder node pair (docs/report.md,
/// "Cattaneo–Mindlin partial slip", gives its errors against the oracle's).
pub struct TfemCattaneo {
    /// The normal step, then one per ratio.
    pub steps: Vec<CattaneoStep>,
    /// Total active-set iterations of the accepted steps.
    pub iterations: usize,
    /// Factorisations over the whole run (trials included).
    pub factorisations: usize,
    /// Least slip dissipation of any element in any accepted step (≥ 0).
    pub min_dissipation: f64,
    /// Wall time of the whole run (trials included).
    pub seconds: f64,
}

/// A block top node and the cylinder node at its x, with that x and its
/// tributary length.
type NodePair = (usize, usize, f64, f64);

impl CattaneoScene {
    /// Node pairs (block top node, cylinder node) at equal x, with their x
    /// and tributary length, sorted by x.
    fn node_pairs(&self) -> Result<Vec<NodePair>> {
        let mesh = self
            .model
            .mesh()
            .ok_or_else(|| Error::state("cattaneo: no mesh"))?;
        let x = mesh.nodes();
        let (lower, upper) = (
            super::nodes_by_x(mesh, TAG_BLOCK_TOP),
            super::nodes_by_x(mesh, TAG_CYLINDER),
        );
        let mut pairs = Vec::new();
        for (i, &l) in lower.iter().enumerate() {
            let Some(&u) = upper.iter().find(|&&u| x[u][0] == x[l][0]) else {
                continue;
            };
            let left = if i > 0 { x[lower[i - 1]][0] } else { x[l][0] };
            let right = lower.get(i + 1).map_or(x[l][0], |&r| x[r][0]);
            pairs.push((l, u, x[l][0], 0.5 * (right - left)));
        }
        Ok(pairs)
    }

    /// The TFEM step at platen displacement (δₜ, −δₙ), as the oracle's
    /// step type.
    fn tfem_step(
        &mut self,
        platen: [f64; 2],
        (apexes, node_pairs): (&[usize], &[NodePair]),
    ) -> Result<(FrictionalStep, ContactReport)> {
        let t0 = std::time::Instant::now();
        for &v in &self.platen {
            self.model.set_prescribed(v, Component::X, platen[0])?;
            self.model.set_prescribed(v, Component::Y, platen[1])?;
        }
        let report = self.model.step(1.0, &ContactOptions::default())?;
        let f = self.model.contact_forces()?;
        let u: Vec<f64> = self
            .model
            .displacements()?
            .iter()
            .flat_map(|d| *d)
            .collect();
        // A pair's state is that of the elements of B measuring it (their
        // apex is one of its nodes): slip if one slips, else stick if one
        // sticks. Its nodal forces add two elements' tractions, whose ratio
        // is μ only where both slip with the same weights.
        let mut state_at = vec![0u8; f.len()];
        let states = self.model.contact_friction_state()?;
        for (&apex, &st) in apexes.iter().zip(&states) {
            state_at[apex] = state_at[apex].max(st);
        }
        let pairs = node_pairs
            .iter()
            .map(|&(lower, upper, x, length)| {
                let [ft, fnorm] = f[upper];
                let state = match state_at[lower].max(state_at[upper]) {
                    0 => PairState::Open,
                    1 => PairState::Stick,
                    _ => PairState::Slip,
                };
                PairResult {
                    lower,
                    upper,
                    x,
                    length,
                    state,
                    normal_force: fnorm.max(0.0),
                    tangential_force: ft,
                    normal: fnorm.max(0.0) / length,
                    tangential: ft / length,
                    gap: 0.0,
                    jump: u[2 * upper] - u[2 * lower],
                    slip_increment: f64::NAN,
                }
            })
            .collect();
        let step = FrictionalStep {
            u,
            reactions: Vec::new(),
            pairs,
            iterations: report.iterations,
            seconds: t0.elapsed().as_secs_f64(),
        };
        Ok((step, report))
    }

    /// Solves the scene with TFEM's frictional elements (μ = `cm.mu` on the
    /// pair): the normal step to the load P of the target a (in
    /// `cm.normal_steps` equal increments of δₙ), then one
    /// tangential step per ratio Q/(μP), each found by secant iterations
    /// on a step that is reverted until it hits its target (to 1e-9).
    pub fn solve_tfem(&mut self, cm: &CattaneoMindlin, ratios: &[f64]) -> Result<TfemCattaneo> {
        let t_start = std::time::Instant::now();
        self.model.set_friction(0, cm.mu)?;
        // B and the node pairs stay the same over every step and trial.
        let apexes: Vec<usize> = self
            .model
            .contact_mesh()?
            .iter()
            .map(|el| el.apex)
            .collect();
        let node_pairs = self.node_pairs()?;
        let fixed = (apexes.as_slice(), node_pairs.as_slice());
        let tol = 1e-9;
        let target = self.load;
        let (mut factorisations, mut iterations) = (0, 0);
        let mut min_dissipation = f64::INFINITY;
        let mut steps = Vec::new();
        // Secant on one step's residual; the last trial is kept.
        let mut secant = |scene: &mut CattaneoScene,
                          platen: &dyn Fn(f64) -> [f64; 2],
                          residual: &dyn Fn(&FrictionalStep) -> f64,
                          (x0, y0, guess): (f64, f64, f64),
                          scale: f64|
         -> Result<(f64, FrictionalStep, usize)> {
            let mut pts = vec![(x0, y0)];
            let mut x = guess;
            for trial in 1..=40 {
                let (s, report) = scene.tfem_step(platen(x), fixed)?;
                factorisations += report.info.factorizations;
                let y = residual(&s);
                if y.abs() <= tol * scale {
                    iterations += report.iterations;
                    let d = scene.model.contact_dissipation()?;
                    min_dissipation = d.iter().fold(min_dissipation, |m, &v| m.min(v));
                    return Ok((x, s, trial));
                }
                scene.model.revert_step()?;
                pts.push((x, y));
                let ((xa, ya), (xb, yb)) = (pts[pts.len() - 2], pts[pts.len() - 1]);
                x = xb - yb * (xb - xa) / (yb - ya);
            }
            Err(Error::new(
                crate::error::Status::NotConverged,
                "cattaneo (TFEM): a load target was not reached",
            ))
        };
        let t0 = std::time::Instant::now();
        let p_of = |s: &FrictionalStep| s.contact_resultant()[0] - target;
        let d0 = target / cm.e_star();
        let (mut dn, mut normal, mut trials) =
            secant(self, &|dn| [0.0, -dn], &p_of, (0.0, -target, d0), target)?;
        let ns = cm.normal_steps.max(1);
        // The increments' counts (the secant holds the totals borrowed).
        let (mut inc_factorisations, mut inc_iterations) = (0, 0);
        if ns > 1 {
            // The same load in `ns` equal increments of δₙ (the last one
            // found by the secant again): an element that closes in an
            // increment carries no shear in it and sticks from its end
            // (docs/method.md §6.15), so increments resolve where along the
            // load each element closes.
            self.model.revert_step()?;
            for i in 1..ns {
                let (_, report) = self.tfem_step([0.0, -dn * i as f64 / ns as f64], fixed)?;
                inc_factorisations += report.info.factorizations;
                inc_iterations += report.iterations;
            }
            let y = p_of(&self.tfem_step([0.0, -dn], fixed)?.0);
            self.model.revert_step()?;
            (dn, normal, trials) = secant(
                self,
                &|dn| [0.0, -dn],
                &p_of,
                (dn, y, dn * (1.0 + 1e-3)),
                target,
            )?;
        }
        steps.push(self.measure(cm, normal, [0.0, -dn], 0.0, trials, t0)?);
        let mut slope = cm.e_star();
        for &ratio in ratios {
            let t0 = std::time::Instant::now();
            let prev = steps.last().expect("the normal step");
            let dt_prev = prev.platen[0];
            let residual = |s: &FrictionalStep| {
                let [p, lt] = s.contact_resultant();
                -lt - ratio * cm.mu * p
            };
            let y_prev = residual(&prev.step);
            let guess = dt_prev - y_prev / slope;
            let (dt, step, trials) = secant(
                self,
                &|dt| [dt, -dn],
                &residual,
                (dt_prev, y_prev, guess),
                cm.mu * target,
            )?;
            slope = -y_prev / (dt - dt_prev);
            steps.push(self.measure(cm, step, [dt, -dn], ratio, trials, t0)?);
        }
        Ok(TfemCattaneo {
            steps,
            iterations: iterations + inc_iterations,
            factorisations: factorisations + inc_factorisations,
            min_dissipation,
            seconds: t_start.elapsed().as_secs_f64(),
        })
    }
}

/// How the platen of [`CattaneoScene::combined`] is moved: to
/// (`ratio`·δₙ, −δₙ), δₙ = P/E* (the load's guess of the normal move), in
/// `steps` equal load steps, or by one contact solve (`steps` = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CombinedLoad {
    /// The platen's sideways move per unit of its normal move.
    pub ratio: f64,
    /// Load steps (0: one contact solve).
    pub steps: usize,
}

/// The block's top after a combined load ([`CattaneoScene::combined`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CombinedResult {
    /// Q/P of the contact forces on the block's top.
    pub q_over_p: f64,
    /// μp₀, p₀ the largest nodal pressure.
    pub mu_p0: f64,
    /// Per block top node, by x: (x, pressure, shear along +x), from the
    /// nodal tractions.
    pub tractions: Vec<(f64, f64, f64)>,
    /// Elements of B slipping at the end.
    pub slipping: usize,
    /// Active-set iterations over every step.
    pub iterations: usize,
    /// Wall time of the steps (or the solve) alone.
    pub seconds: f64,
}

impl CombinedResult {
    /// ‖q − (Q/P)p‖ / ‖(Q/P)p‖ over the block's top nodes: the distance
    /// of the shear from Mindlin's answer for proportional loading below
    /// μ, q = (Q/P)·p.
    pub fn off_proportional(&self) -> f64 {
        let (mut off, mut size) = (0.0, 0.0);
        for &(_, p, q) in &self.tractions {
            off += (q - self.q_over_p * p).powi(2);
            size += (self.q_over_p * p).powi(2);
        }
        (off / size).sqrt()
    }

    /// max |q − q_other| / (μp₀) over the block's top nodes.
    pub fn shear_difference(&self, other: &CombinedResult) -> f64 {
        self.tractions
            .iter()
            .zip(&other.tractions)
            .map(|(a, b)| (a.2 - b.2).abs() / self.mu_p0)
            .fold(0.0, f64::max)
    }
}

impl CattaneoScene {
    /// The normal and tangential loads together (docs/method.md §6.15):
    /// the platen moved along (ratio·δₙ, −δₙ) as `load` says, with
    /// friction μ = `mu`, from rest.
    pub fn combined(&mut self, cm: &CattaneoMindlin, load: CombinedLoad) -> Result<CombinedResult> {
        let m = &mut self.model;
        m.set_friction(0, cm.mu)?;
        let dn = self.load / cm.e_star();
        for &v in &self.platen {
            m.set_prescribed(v, Component::X, load.ratio * dn)?;
            m.set_prescribed(v, Component::Y, -dn)?;
        }
        let options = ContactOptions::default();
        let t0 = std::time::Instant::now();
        let mut iterations = 0;
        if load.steps == 0 {
            iterations += m.solve_contact(&options)?.iterations;
        }
        for i in 1..=load.steps {
            iterations += m.step(i as f64 / load.steps as f64, &options)?.iterations;
        }
        let seconds = t0.elapsed().as_secs_f64();
        let mesh = m.mesh().ok_or_else(|| Error::state("cattaneo: no mesh"))?;
        let block_top = super::nodes_by_x(mesh, TAG_BLOCK_TOP);
        let x = mesh.nodes();
        let f = m.contact_forces()?;
        let (p, q) = block_top
            .iter()
            .fold((0.0, 0.0), |(p, q), &v| (p - f[v][1], q + f[v][0]));
        let t = m.contact_nodal_tractions()?;
        // The block's tangent runs along −x on its top (outward normal +y).
        let tractions: Vec<(f64, f64, f64)> = block_top
            .iter()
            .map(|&v| (x[v][0], t[v][0], -t[v][1]))
            .collect();
        let p0 = tractions.iter().map(|r| r.1).fold(0.0, f64::max);
        let states = m.contact_friction_state()?;
        Ok(CombinedResult {
            q_over_p: q / p,
            mu_p0: cm.mu * p0,
            tractions,
            slipping: states.iter().filter(|&&s| s == 2).count(),
            iterations,
            seconds,
        })
    }
}
