//! The funicular polygon itself (Seilpolygon, LH C.2, Abb. 22), one construction for every
//! procedure that draws one: force systems, beams (and the shafts built of them) and the
//! reactions of trusses. Each caller keeps its own pole rule and draws its own force polygon;
//! the pole, its rays, the strings between the lines of action and the closing line are drawn
//! here, with one set of captions.
//!
//! ```
//! use graphostatik::prelude::*;
//! use graphostatik::statics::funicular::polygon::{pole_and_rays, strings, StringStyle};
//! // Two downward forces of 100 and 200 kg, 3 m apart, drawn at 1 mm = 1 m and 1 mm = 10 kg.
//! let mut b = Board::recording();
//! let n = Note::new("given", Topic::Loads);
//! let down = Vector::new(0.0, -1.0);
//! let a1 = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
//! let a2 = b.point(Point::new(3.0, 0.0), Role::Given, n.clone());
//! let lines = [
//!     b.line_dir(&a1, down, Role::Construction, n.clone())?,
//!     b.line_dir(&a2, down, Role::Construction, n.clone())?,
//! ];
//! let plan: Vec<_> = [20.0, 10.0, -10.0]
//!     .iter()
//!     .map(|&y| b.point(Point::new(10.0, y), Role::Given, n.clone()))
//!     .collect();
//! let rays = pole_and_rays(&mut b, Point::new(25.0, 0.0), &plan)?;
//! let s = strings(&mut b, &rays.rays, &a1, true, StringStyle::RESULT, |_, j| Ok(lines[j]))?;
//! // The outer strings meet on the resultant, at the lever rule: x = 200·3/300 = 2 m.
//! let Cut::Point(x, _) = b.meet(&s.strings[0], &s.strings[2], Label::NONE, n) else { panic!() };
//! assert!((x.g.x - 2.0).abs() < 1e-12);
//! # Ok::<(), ConstructionError>(())
//! ```

use crate::kernel::{Line, Point};
use crate::protocol::{note, Board, ConstructionError, Label, Note, Part, Role, Topic, H};

const N_POLE: Note = note("pole O", Some("Pol"), "LH C.2, Abb. 22", Topic::ForcePlan);
const N_RAY: Note = note(
    "pole ray",
    Some("Polstrahl"),
    "LH C.2, Abb. 22",
    Topic::ForcePlan,
);
const N_STRING: Note = note(
    "string parallel to the pole ray",
    Some("Seilseite"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
const N_CORNER: Note = note(
    "string cuts the next line of action",
    Some("Seileck"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
const N_CLOSING: Note = note(
    "closing line",
    Some("Schlusslinie"),
    "LH C.4, Abb. 24",
    Topic::Reactions,
);
const N_CLOSING_RAY: Note = note(
    "parallel to the closing line through the pole",
    Some("Parallele zur Schlusslinie"),
    "LH C.4, Abb. 24",
    Topic::Reactions,
);

/// The pole O and its rays to the corners of the force polygon.
#[derive(Debug, Clone, PartialEq)]
pub struct Rays {
    /// The pole.
    pub pole: H<Point>,
    /// Ray k runs from the pole to corner k of the force polygon (`corners.len()` rays).
    pub rays: Vec<H<Line>>,
}

/// The number a ray or string is lettered with: LH numbers them from 1 (Abb. 24: "die
/// Polstrahlen 1, 2, 3 und 4 …, worauf parallel zu diesen das Seilpolygon … gebildet wird"),
/// a string with its ray's number.
fn number(k: usize) -> Label {
    Label::named((k + 1).to_string())
}

/// The Roman numeral of `k` ≥ 1 (I, II, … XL …), as LH names the corners of a funicular
/// polygon (Abb. 24: I, II, III, IV and V).
pub fn roman(k: usize) -> String {
    const DIGITS: [(usize, &str); 13] = [
        (1000, "M"),
        (900, "CM"),
        (500, "D"),
        (400, "CD"),
        (100, "C"),
        (90, "XC"),
        (50, "L"),
        (40, "XL"),
        (10, "X"),
        (9, "IX"),
        (5, "V"),
        (4, "IV"),
        (1, "I"),
    ];
    let (mut k, mut out) = (k, String::new());
    for (v, d) in DIGITS {
        while k >= v {
            out.push_str(d);
            k -= v;
        }
    }
    out
}

/// Places the pole (chosen by the caller's rule) and draws its rays to the corners of the
/// force polygon, numbered 1, 2, … as LH numbers them.
///
/// # Errors
/// [`ConstructionError::Unsupported`] on input `pole` where the pole lies on a corner.
pub fn pole_and_rays(
    b: &mut Board,
    pole_at: Point,
    corners: &[H<Point>],
) -> Result<Rays, ConstructionError> {
    let pole = b.point(pole_at, Role::Given.named("O"), N_POLE);
    let mut rays = Vec::with_capacity(corners.len());
    // Each ray named within the caller’s context ("dead load: ray 2").
    let base = b.context();
    for (i, p) in corners.iter().enumerate() {
        b.set_context_within(base.as_deref(), || format!("ray {i}"));
        let ray = b
            .line_through(&pole, p, Role::Construction.labelled(number(i)), N_RAY)
            .map_err(|_| {
                ConstructionError::unsupported(
                    "pole",
                    format!(
                        "the pole lies on corner {i} of the force polygon: choose another pole"
                    ),
                )
            })?;
        rays.push(ray);
    }
    b.restore_context(base);
    Ok(Rays { pole, rays })
}

/// How the strings are drawn: as the result (force systems, beams, whose polygon is the
/// moment area) or as construction lines (truss reactions). Either way each string bears
/// its ray's number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StringStyle {
    /// The role of the strings.
    pub role: Role,
    /// Whether the polygon's corners are lettered with Roman numerals (LH Abb. 24's I, II,
    /// …): not where the polygon is drawn over a truss whose joints bear those names.
    pub corners_named: bool,
}

impl StringStyle {
    /// Heavy: the polygon is a result, its corners named.
    pub const RESULT: StringStyle = StringStyle {
        role: Role::Result,
        corners_named: true,
    };
    /// Thin: the polygon only serves the reactions; its corners stay unnamed.
    pub const CONSTRUCTION: StringStyle = StringStyle {
        role: Role::Construction,
        corners_named: false,
    };
}

/// The strings of a funicular polygon and its corners on the lines of action.
#[derive(Debug, Clone, PartialEq)]
pub struct Strings {
    /// String k is parallel to ray k: string 0 before the first force, string n after the
    /// last.
    pub strings: Vec<H<Line>>,
    /// Corner j, where string j meets line of action j (string j + 1 leaves it).
    pub corners: Vec<H<Point>>,
}

/// Draws the strings: the first parallel to ray 0 through `start`, then at each line of
/// action (made on demand by `line_of_action(board, j)`, so that a caller may draw it just
/// before its cut) the next string from the corner where the last one cuts it. Where
/// `start_on_first` the start is the first corner itself (it lies on the first line of
/// action); otherwise the first string is cut with it too. Each string bears its ray's
/// number; the corners are named on from the start's I (II, III, …) where the style says.
///
/// # Errors
/// [`ConstructionError::Unsupported`] on input `pole` where a string runs parallel to the
/// line of action it should cut (the pole lies on that side of the force polygon).
pub fn strings(
    b: &mut Board,
    rays: &[H<Line>],
    start: &H<Point>,
    start_on_first: bool,
    style: StringStyle,
    mut line_of_action: impl FnMut(&mut Board, usize) -> Result<H<Line>, ConstructionError>,
) -> Result<Strings, ConstructionError> {
    let n = rays.len().saturating_sub(1);
    let mut strings = Vec::with_capacity(n + 1);
    let mut corners = Vec::with_capacity(n);
    // Each string and corner named within the caller's context ("dead load: string 2"),
    // which the line of action, the caller's own step, keeps.
    let base = b.context();
    b.set_context_within(base.as_deref(), || "string 0".into());
    let string = |k: usize| style.role.labelled(number(k));
    strings.push(b.parallel(&rays[0], start, string(0), N_STRING));
    for j in 0..n {
        let corner = if j == 0 && start_on_first {
            *start
        } else {
            b.restore_context(base.clone());
            let line = line_of_action(b, j)?;
            b.set_context_within(base.as_deref(), || {
                format!("corner {j} of the string polygon")
            });
            // The start is I; the corners follow on, II on the first line of action cut.
            let name = match style.corners_named {
                true => Label::named(roman(j + 1 + usize::from(!start_on_first))),
                false => Label::quiet("II", j as u32),
            };
            b.meet_point(&strings[j], &line, name, N_CORNER)
                .map_err(|_| {
                    ConstructionError::unsupported(
                        "pole",
                        format!(
                            "string {j} runs parallel to the line of action of force {}: the pole lies on that side of the force polygon; choose another pole",
                            j + 1
                        ),
                    )
                })?
        };
        corners.push(corner);
        b.set_context_within(base.as_deref(), || format!("string {}", j + 1));
        strings.push(b.parallel(&rays[j + 1], &corner, string(j + 1), N_STRING));
    }
    b.restore_context(base);
    Ok(Strings { strings, corners })
}

/// The closing line (Schlusslinie) and its parallel through the pole, which divides the
/// force polygon into the reactions (LH C.4, Abb. 24).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closing {
    /// The closing line.
    pub line: H<Line>,
    /// Its parallel through the pole.
    pub ray: H<Line>,
}

/// Draws the closing line from `a` to `z` (the outer strings' points on the two supports'
/// lines) and its parallel through the pole, numbered after the `rays` rays as LH numbers
/// it (Abb. 24: "durch O die Parallele I–V = 5"); `label` and `role` are the caller's
/// drawing choice for the line, `ray_role` for the parallel.
#[allow(clippy::too_many_arguments)]
pub fn closing(
    b: &mut Board,
    a: &H<Point>,
    z: &H<Point>,
    pole: &H<Point>,
    (label, role): (Label, Role),
    rays: usize,
    ray_role: Role,
) -> Result<Closing, ConstructionError> {
    let line = b.line_through(a, z, role.labelled(label), N_CLOSING)?;
    let ray = b.parallel(&line, pole, ray_role.labelled(number(rays)), N_CLOSING_RAY);
    Ok(Closing { line, ray })
}

/// [`closing`] in a figure whose funicular polygon and force polygon are parts of their own
/// (a truss's drawing and its reactions' polygon): the unlettered closing line drawn in the
/// board's part, its parallel through the pole in `ray_part`, where the board goes on drawing.
pub fn closing_across(
    b: &mut Board,
    (a, z): (&H<Point>, &H<Point>),
    pole: &H<Point>,
    role: Role,
    ray_part: Part,
) -> Result<Closing, ConstructionError> {
    let line = b.line_through(a, z, role.labelled(Label::NONE), N_CLOSING)?;
    b.set_part(ray_part);
    let ray = b.parallel(&line, pole, role, N_CLOSING_RAY);
    Ok(Closing { line, ray })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Vector;

    fn given(b: &mut Board, x: f64, y: f64) -> H<Point> {
        b.point(
            Point::new(x, y),
            Role::Given,
            Note::new("given", Topic::Loads),
        )
    }

    #[test]
    fn a_pole_on_a_corner_is_named() {
        let mut b = Board::silent();
        let c = [given(&mut b, 0.0, 0.0), given(&mut b, 0.0, -10.0)];
        let e = pole_and_rays(&mut b, Point::new(0.0, -10.0), &c).unwrap_err();
        assert!(matches!(&e, ConstructionError::Unsupported { input, .. } if input == "pole"));
    }

    #[test]
    fn a_string_along_its_line_of_action_is_named() {
        let mut b = Board::recording();
        // A pole level with the force polygon's corner 1: ray 1 is horizontal, and so is the
        // second line of action.
        let c = [
            given(&mut b, 0.0, 10.0),
            given(&mut b, 0.0, 0.0),
            given(&mut b, 10.0, 0.0),
        ];
        let r = pole_and_rays(&mut b, Point::new(20.0, 0.0), &c).unwrap();
        let a = given(&mut b, 0.0, 0.0);
        let horizontal = b
            .line_dir(&a, Vector::new(1.0, 0.0), Role::Given, N_STRING)
            .unwrap();
        let vertical = b
            .line_dir(&a, Vector::new(0.0, 1.0), Role::Given, N_STRING)
            .unwrap();
        let lines = [vertical, horizontal];
        let e = strings(&mut b, &r.rays, &a, true, StringStyle::RESULT, |_, j| {
            Ok(lines[j])
        })
        .unwrap_err();
        assert!(e.to_string().contains("string 1 runs parallel"), "{e}");
    }

    #[test]
    fn closing_line_through_the_pole() {
        let mut b = Board::recording();
        let (a, z, o) = (
            given(&mut b, 0.0, 0.0),
            given(&mut b, 10.0, 5.0),
            given(&mut b, 3.0, 3.0),
        );
        let c = closing(
            &mut b,
            &a,
            &z,
            &o,
            (Label::NONE, Role::Given),
            4,
            Role::Auxiliary,
        )
        .unwrap();
        assert_eq!(b.object(c.ray.id).unwrap().label.to_string(), "5");
        assert!(crate::kernel::cross(&c.line.g.dir, &c.ray.g.dir).abs() < 1e-15);
        assert_eq!(c.ray.g.origin, o.g);
    }
}
