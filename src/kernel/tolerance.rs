//! Every tolerance of the engine, in one place.
//!
//! Geometry is constructed on the *drawing sheet*: lengths are millimetres of paper, as the
//! drafter's ruler measures them. Tolerances that decide a geometric case (parallel, tangent,
//! coincident) are relative to the size of the figure, so a construction behaves the same at
//! 1 : 1 and at 1 : 50. No other module writes a numeric literal tolerance.

/// Relative length tolerance: two lengths on the sheet that differ by less than
/// `REL_LENGTH_EPS × figure size` are the same length. Used to decide tangency and coincidence.
///
/// 1e-12 leaves three decimal digits of headroom above f64's 2.2e-16 for the few operations
/// (a normalisation, a product, a square root) that feed such a decision.
pub const REL_LENGTH_EPS: f64 = 1e-12;

/// Two unit directions whose cross product (the sine of the angle between them) is below this
/// are parallel. Dimensionless (radians for small angles); at 1e-12 rad two lines 1 km long on
/// the sheet would drift apart by a nanometre.
pub const PARALLEL_SIN_EPS: f64 = 1e-12;

/// Meeting angle below which an intersection is a *schleifender Schnitt* (glancing
/// intersection), in radians (15°). Drafting practice: below about 15° a pencil line of 0.2 mm
/// width smears the intersection along the line by more than 0.2 mm / sin 15° ≈ 0.8 mm.
/// The intersection is still computed exactly; the step is flagged.
pub const GLANCING_ANGLE: f64 = 15.0 * std::f64::consts::PI / 180.0;

/// Relative tolerance of a check of a constructed value against its closed form:
/// `|constructed − closed| ≤ CHECK_REL × max(|closed|, reference)`, where `reference` is the
/// natural magnitude of the quantity (the crank radius for a piston path, the crank-pin speed
/// for a piston velocity, the piston force for a force). The reference makes the check absolute
/// at figure scale where the value itself passes through zero (dead centres).
pub const CHECK_REL: f64 = 1e-9;

/// Relative slack when a chosen scale is rounded up to a nice one: a wanted scale within this
/// fraction above a nice value (2.5000000000001 from a quotient) takes that value instead of
/// jumping to the next one.
pub const NICE_SCALE_SLACK: f64 = 1e-12;

/// Two positions along a beam or a line (m) closer than `REL_POSITION_EPS × span` are one
/// place: a section asked for at a load is the load's section, two events of the shear
/// diagram at one x are one event. At 1e-12 it sits three digits above f64's rounding of a
/// position given in the scene.
pub const REL_POSITION_EPS: f64 = 1e-12;

/// A crossing (a zero moment) counts as inside a stretch of the beam only when it lies more
/// than `REL_STRETCH_EPS × span` inside its ends: a crossing at an end is the neighbouring
/// stretch's, and a computed intersection of two nearly parallel lines carries more error than
/// a given position (1e-9 leaves room for a conditioning of 1e6).
pub const REL_STRETCH_EPS: f64 = 1e-9;

/// Two candidates for a largest value (the largest |M| of a beam) within `REL_TIE_EPS` times
/// their reference are a tie, and the first found is kept: the order of the construction,
/// not rounding, decides which section is named.
pub const REL_TIE_EPS: f64 = 1e-12;

/// A support reaction below this fraction of the largest external force is no force at all
/// (an unloaded roller): it is left out of the outline of Bow's notation. The plan is exact
/// to about 1e-15 of the loads, three digits below.
pub const REL_ZERO_REACTION: f64 = 1e-12;

/// Two unknown members at a joint whose directions make a sine below this are in line: their
/// parallels would cut at a glancing angle of under 2e-7°, and the joint is left for later
/// (another joint, or a section, finds one of them). Dimensionless.
pub const JOINT_CUT_SIN_EPS: f64 = 1e-9;

/// A triangle of a polygon's fan whose area is below `REL_AREA_EPS × size²` (size: the
/// polygon's largest extent) is a sliver: it has no centroid to construct and adds nothing.
pub const REL_AREA_EPS: f64 = 1e-12;

/// Two joints whose motion in a truss's free motion differs by less than this fraction move
/// alike, and the first is named: the name of the joint that can move must not depend on the
/// rounding of the singular value decomposition (which is good to about 1e-13 here).
pub const REL_TIE_EPS_MOTION: f64 = 1e-9;

/// Two directions given in degrees that differ by less than this from 0° or 180° are
/// parallel (a resolution along them has no solution). 1e-9° is a sine of 1.7e-11, a few
/// digits above where the 2×2 solve loses its last digit.
pub const PARALLEL_DEG_EPS: f64 = 1e-9;

/// A crossing of two curves over the crank angle (the turning force and its mean, LH J) is
/// located to this many degrees. The energy curve is stationary there, so ΔE moves by
/// ½·T′·δ², some 1e-20 of it: the tolerance only bounds the search, far below what the
/// value can show.
pub const CROSSING_DEG_EPS: f64 = 1e-10;

/// A segment or force shorter than this on the sheet (mm) is not drawn: a zero force (N at a
/// dead centre) has no direction for its arrowhead. A nanometre of paper, far below a pen.
pub const MIN_DRAWN_MM: f64 = 1e-9;

/// Two segments whose ends lie closer than this on the sheet (mm) are one line to the eye:
/// a quarter of the thinnest pen (0.18 mm). Members of equal force in a plan (a chord's
/// panels, the members of an unloaded cantilever) share a line and one label, "S₁, S₂".
pub const SAME_LINE_MM: f64 = 0.045;

/// A force below this many kg is written as 0 and classed as a zero-force member: the plan
/// is exact to about 1e-12 of the loads, so anything below a gram is rounding.
pub const ZERO_KG: f64 = 1e-3;

/// A singular value of the equilibrium matrix below this fraction of the largest counts as
/// zero. The matrix entries are direction cosines (of size 1), so the largest singular value
/// is of order 1 to √(max degree); a mechanism's zero comes out at the rounding of the
/// decomposition, about √n·ε ≈ 1e-15 for a thousand joints, and 1e-13 stays above that.
/// A determinate truss however flat is determinate: a triangle whose apex is 1e-10 of its
/// span has a smallest singular value of about 1e-10, and was refused as a mechanism by the
/// earlier 1e-10 (its plan's cuts are now flagged as glancing instead).
pub const RANK_REL: f64 = 1e-13;

/// A lever arm below this fraction of the truss's size ([`Truss::size`](crate::truss::Truss::size), like the kernel's
/// lengths), or a sine between two reaction lines below it, counts as zero: the supports
/// then cannot be resolved by moments.
pub const LEVER_REL: f64 = 1e-12;

/// A member force at most this fraction of the largest external force is a zero-force
/// member (Nullstab): the plan is exact to about 1e-12 of the loads, so 1e-9 separates
/// rounding from a real force with room on both sides.
pub const ZERO_FORCE_REL: f64 = 1e-9;

/// A force below this (kg) counts as zero when deciding whether a flat bar is compressed:
/// the plan is exact to about 1e-12 of the loads.
pub const SLACK_KG: f64 = 1e-6;

/// A length below this fraction of its figure's span counts as zero where a construction
/// chooses its own layout (the side of a pole, whether a force polygon closes, whether a
/// point lies on a drawn circle): the choice changes the drawing, never a result. Also a lever
/// arm of a section (LH B.4) below it against the truss's size: the section gives no force.
pub const REL_LAYOUT_EPS: f64 = 1e-9;

/// A candidate (a pole, a roller to resolve by) replaces the best so far only when its score
/// (a sine, dimensionless) beats it by this fraction: rounding never picks the drawing.
pub const REL_SCORE_EPS: f64 = 1e-9;

/// A force polygon whose closing side R is shorter than this fraction of the sum of its sides
/// is closed: R is judged against the forces, not against the sheet (two forces of 1000 and
/// 999.999999999 kg leave R = 1e-9 kg, rounding, and a couple of their moment).
pub const REL_CLOSURE_EPS: f64 = 1e-12;

/// A slider-crank's rod must be longer than its crank by at least this fraction of the crank
/// (L/R ≥ 1 + 1e-6): nearer to locking, the cut of the rod's arc with the piston line at
/// 90° is so glancing (its amplification grows as 1/√(L/R − 1)) that the forces read off it
/// lose more digits than their checks allow. At 1 + 1e-7 every check still passes.
pub const MIN_ROD_EXCESS: f64 = 1e-6;

/// A figure whose data lie farther from the scene's origin than this many times their own
/// size is constructed in a local frame (a beam from its support A): an offset of 1e6 m
/// would otherwise take six of f64's sixteen digits from every position on the sheet and
/// from the closed forms.
pub const REL_LOCAL_FRAME: f64 = 100.0;

/// Largest number of equal divisions of a segment, arc or crank circle a scene may ask for.
/// A drafter divides into 8 to 36 parts; 3,600 is a benchmark size, 100,000 is absurd for a
/// figure and would write a figure of hundreds of megabytes.
pub const MAX_DIVISIONS: usize = 3600;

/// The length tolerance of a figure: `REL_LENGTH_EPS` times its size.
///
/// ```
/// use graphostatik::kernel::Tolerance;
/// let tol = Tolerance::for_figure(250.0);
/// assert_eq!(tol.length, 250.0 * graphostatik::kernel::tolerance::REL_LENGTH_EPS);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Tolerance {
    /// Absolute length tolerance on the sheet, in mm.
    pub length: f64,
}

impl Tolerance {
    /// The tolerance for a figure whose largest extent is `size` mm on the sheet.
    /// A non-finite or non-positive size falls back to 1 mm (the figure is then degenerate
    /// anyway, and a scene validator has rejected it before).
    pub fn for_figure(size: f64) -> Self {
        let size = if size.is_finite() && size > 0.0 {
            size
        } else {
            1.0
        };
        Tolerance {
            length: size * REL_LENGTH_EPS,
        }
    }
}

/// The smallest a diagram may be drawn against its sheet: a velocity or acceleration curve,
/// a force plan whose largest ordinate is less than this times the figure's extent is drawn
/// in coordinates whose rounding (2⁻⁵³ of the sheet) is more than 1e-10 of the diagram, and
/// a cut amplifying that would fail its 1e-9 check. Refused at validation, naming the scale.
pub const MIN_PART_REL: f64 = 1e-6;

/// The rounding an operation of the kernel adds, relative to the magnitude it computes: four
/// units of f64's roundoff (2⁻⁵³ each), for the few products, sums and one normalisation or
/// square root of a step. The propagated error bound of a constructed value (the protocol's
/// `Check::bound`) starts from this at every step and is amplified by every cut downstream.
pub const OP_ROUNDOFF: f64 = 4.0 * (f64::EPSILON / 2.0);
