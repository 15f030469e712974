//! The words of the beam construction's steps.

use crate::protocol::{note, Note, Topic};

pub(super) const N_BEAM_START: Note = note(
    "left end of the beam",
    Some("Trägerende"),
    "LH Abb. 24",
    Topic::Loads,
);
pub(super) const N_BEAM_AXIS: Note =
    note("beam axis", Some("Trägerachse"), "LH Abb. 24", Topic::Loads);
pub(super) const N_BEAM_END: Note = note(
    "right end of the beam",
    Some("Trägerende"),
    "LH Abb. 24",
    Topic::Loads,
);
pub(super) const N_BEAM: Note = note("the beam", Some("Träger"), "LH Abb. 24", Topic::Loads);
pub(super) const N_SUPPORT: Note = note("support", Some("Auflager"), "LH Abb. 24", Topic::Loads);
pub(super) const N_SUPPORT_SYMBOL: Note = note(
    "support drawn",
    Some("Auflager"),
    "LH Abb. 24",
    Topic::Loads,
);
pub(super) const N_SUPPORT_VERTICAL: Note = note(
    "vertical through the support",
    Some("Auflagersenkrechte"),
    "LH Abb. 24",
    Topic::Loads,
);
pub(super) const N_LOAD: Note = note("point load", Some("Einzellast"), "LH Abb. 24", Topic::Loads);
pub(super) const N_LOAD_ARROW: Note = note(
    "point load drawn",
    Some("Einzellast"),
    "LH Abb. 24",
    Topic::Loads,
);
pub(super) const N_UNIFORM: Note = note(
    "uniform load",
    Some("gleichmäßig verteilte Last"),
    "LH Abb. 36",
    Topic::Loads,
);
pub(super) const N_UNIFORM_RESULTANT: Note = note(
    "its resultant Q = q·l at the centre",
    Some("Mittelkraft im Schwerpunkt"),
    "LH Abb. 36",
    Topic::Loads,
);
pub(super) const N_LOAD_VERTICAL: Note = note(
    "line of action of the load",
    Some("Kraftrichtung"),
    "LH Abb. 22, 24",
    Topic::Loads,
);
pub(super) const N_END_VERTICAL: Note = note(
    "vertical through an end of the uniform load",
    Some("Lastgrenze"),
    "LH Abb. 36",
    Topic::Loads,
);
pub(super) const N_LOAD_LINE_START: Note = note(
    "start of the load line",
    Some("Kräftepolygon"),
    "LH Abb. 24",
    Topic::ForcePlan,
);
pub(super) const N_LOAD_LINE: Note = note(
    "load line",
    Some("Kräftepolygon"),
    "LH Abb. 24",
    Topic::ForcePlan,
);
pub(super) const N_LAY_OFF: Note = note(
    "lay off the load at the force scale",
    Some("Kräftemaßstab"),
    "LH A.1, Abb. 24",
    Topic::ForcePlan,
);
pub(super) const N_START: Note = note(
    "start of the funicular polygon",
    Some("Seilpolygon"),
    "LH Abb. 24",
    Topic::Funicular,
);
pub(super) const N_END_STRING_CUT: Note = note(
    "first or last string cuts the support vertical",
    Some("Seilseite"),
    "LH Abb. 24, 34",
    Topic::Reactions,
);
pub(super) const N_C: Note = note(
    "it cuts the load line: A and B",
    Some("Auflagerdrücke"),
    "LH Abb. 24",
    Topic::Reactions,
);
pub(super) const N_REACTION_A: Note = note(
    "reaction A read off the load line",
    Some("Auflagerdruck A"),
    "LH Abb. 24",
    Topic::Reactions,
);
pub(super) const N_REACTION_B: Note = note(
    "reaction B read off the load line",
    Some("Auflagerdruck B"),
    "LH Abb. 24",
    Topic::Reactions,
);
pub(super) const N_REACTION_ARROW: Note = note(
    "reaction drawn",
    Some("Auflagerdruck"),
    "LH Abb. 24",
    Topic::Reactions,
);
pub(super) const N_POLY_AT: Note = note(
    "the polygon on the vertical of the section",
    Some("Seilpolygon"),
    "LH Abb. 24",
    Topic::Moment,
);
pub(super) const N_REF_AT: Note = note(
    "closing line (or end string) on the vertical of the section",
    Some("Schlußlinie"),
    "LH Abb. 24, 34",
    Topic::Moment,
);
pub(super) const N_ORDINATE: Note = note(
    "ordinate y of the moment area",
    Some("Momentenordinate"),
    "LH Gl. 11",
    Topic::Moment,
);
pub(super) const N_MOMENT: Note = note(
    "bending moment M = y·H",
    Some("Biegungsmoment"),
    "LH Gl. 11",
    Topic::Moment,
);
pub(super) const N_TANGENT_POINT: Note = note(
    "string cuts the vertical at the end of the load: tangent point",
    Some("Berührungspunkt"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_DIVIDE_TANGENT: Note = note(
    "divide the tangent into equal parts",
    Some("Teilung der Tangente"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_ENVELOPE: Note = note(
    "join k–k: a tangent of the parabola",
    Some("Parabeltangente"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_TOUCH: Note = note(
    "the point dividing the join in the same ratio lies on the parabola",
    Some("Parabelpunkt"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_PARABOLA: Note = note(
    "parabola of the uniform load",
    Some("Parabel"),
    "LH Abb. 36, 37",
    Topic::Moment,
);
pub(super) const N_SECTION_VERTICAL: Note = note(
    "vertical through the section",
    Some("Schnitt"),
    "LH Abb. 24",
    Topic::Moment,
);
pub(super) const N_INFLECTION: Note = note(
    "the polygon cuts the closing line: zero moment",
    Some("Wendepunkt"),
    "LH Abb. 34",
    Topic::Moment,
);
pub(super) const N_INFLECTION_X: Note = note(
    "position of the zero moment",
    Some("Querschnitt C"),
    "LH Abb. 34",
    Topic::Moment,
);
pub(super) const N_SHEAR_BASE_START: Note = note(
    "zero line of the shear diagram",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_BASE: Note = note(
    "zero line of the shear diagram",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_FOOT: Note = note(
    "section on the zero line",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_MEASURE: Note = note(
    "shear force from the force plan",
    Some("Querkraft"),
    "LH C.6, Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_ORDINATE: Note = note(
    "transfer the shear force as ordinate",
    Some("Querkraftordinate"),
    "LH Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_DIAGRAM: Note = note(
    "shear diagram",
    Some("Querkraftdiagramm"),
    "LH Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_SIGN: Note = note(
    "the shear's sign: positive up (+), negative down (−)",
    Some("Vorzeichen der Querkraft"),
    "LH C.5, Abb. 25",
    Topic::Shear,
);
pub(super) const N_SHEAR_ZERO: Note = note(
    "the sloping shear line cuts the zero line: largest moment",
    Some("Nullpunkt der Querkraft"),
    "LH Abb. 36, 37",
    Topic::Shear,
);
pub(super) const N_SHEAR_ZERO_X: Note = note(
    "position of the zero shear",
    Some("Nullpunkt"),
    "LH Abb. 36",
    Topic::Shear,
);
pub(super) const N_RATIO_1: Note = note(
    "the same ratio on the first tangent",
    Some("Teilverhältnis"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_RATIO_2: Note = note(
    "the same ratio on the second tangent",
    Some("Teilverhältnis"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_RATIO_JOIN: Note = note(
    "their join, a tangent of the parabola",
    Some("Parabeltangente"),
    "LH Abb. 36",
    Topic::Moment,
);
pub(super) const N_RATIO_POINT: Note = note(
    "the parabola point over the zero shear",
    Some("Parabelpunkt"),
    "LH Abb. 36",
    Topic::Moment,
);

pub(super) const N_STRINGER: Note = note(
    "stringer between two cross beams",
    Some("Zwischenträger"),
    "LH Abb. 35",
    Topic::Loads,
);
pub(super) const N_CROSS_BEAM: Note = note(
    "cross beam at a panel point",
    Some("Querträger"),
    "LH Abb. 35",
    Topic::Loads,
);
pub(super) const N_PANEL_LOAD: Note = note(
    "load on a stringer",
    Some("Last auf dem Zwischenträger"),
    "LH Abb. 35",
    Topic::Loads,
);
