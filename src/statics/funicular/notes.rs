//! The words of the force-system constructions' steps.

use crate::protocol::{note, Note, Topic};

pub(super) const N_APPLICATION: Note = note(
    "point of application",
    Some("Angriffspunkt"),
    "LH A.1, Abb. 1",
    Topic::Loads,
);
pub(super) const N_ARROW: Note = note(
    "force drawn in the position plan",
    Some("Kraft"),
    "LH Abb. 22",
    Topic::Loads,
);
pub(super) const N_LINE: Note = note(
    "line of action",
    Some("Aktionslinie"),
    "LH A.1, Abb. 22",
    Topic::Loads,
);
pub(super) const N_START: Note = note(
    "start of the force polygon",
    Some("Kräftepolygon"),
    "LH A.4, Abb. 7",
    Topic::ForcePlan,
);
pub(super) const N_DIRECTION: Note = note(
    "parallel to the line of action",
    Some("Kraftrichtung"),
    "LH A.4",
    Topic::ForcePlan,
);
pub(super) const N_LAY_OFF: Note = note(
    "lay off the force at the force scale",
    Some("Kräftemaßstab"),
    "LH A.4, Abb. 7",
    Topic::ForcePlan,
);
pub(super) const N_RESULTANT: Note = note(
    "closing side: the resultant R",
    Some("Resultierende"),
    "LH A.3-4, Abb. 5-7",
    Topic::ForcePlan,
);
pub(super) const N_RX: Note = note(
    "horizontal component of R",
    Some("Resultierende"),
    "LH A.4",
    Topic::ForcePlan,
);
pub(super) const N_RY: Note = note(
    "vertical component of R",
    Some("Resultierende"),
    "LH A.4",
    Topic::ForcePlan,
);
pub(super) const N_AXIS_X: Note = note(
    "horizontal through the start",
    Some("Waagerechte"),
    "LH A.4",
    Topic::ForcePlan,
);
pub(super) const N_AXIS_Y: Note = note(
    "vertical through the start",
    Some("Senkrechte"),
    "LH A.4",
    Topic::ForcePlan,
);
pub(super) const N_STRING_START: Note = note(
    "start of the funicular polygon on the first line of action",
    Some("Seilpolygon"),
    "LH Abb. 22",
    Topic::Funicular,
);
pub(super) const N_FIRST_LAST: Note = note(
    "first and last string meet on the resultant",
    Some("Schnitt der äußeren Seilseiten"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
pub(super) const N_R_LINE: Note = note(
    "line of action of the resultant",
    Some("Aktionslinie der Resultierenden"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
pub(super) const N_R_MOMENT: Note = note(
    "moment of R about the origin, read off its line of action",
    Some("Moment"),
    "LH C.2",
    Topic::Funicular,
);
pub(super) const N_COUPLE_FOOT: Note = note(
    "foot of the perpendicular between the parallel outer strings",
    Some("Kräftepaar"),
    "LH C.2",
    Topic::Funicular,
);
pub(super) const N_COUPLE: Note = note(
    "couple: |ray 0| × distance of the outer strings",
    Some("Kräftepaar"),
    "LH C.2",
    Topic::Funicular,
);
pub(super) const N_RESOLVE_LINE: Note = note(
    "parallel to a given direction through an end of the force",
    Some("Kräfteparallelogramm"),
    "LH A.2, Abb. 3",
    Topic::ForcePlan,
);
pub(super) const N_RESOLVE_CUT: Note = note(
    "the parallels meet: the components",
    Some("Kräfteparallelogramm"),
    "LH A.2, Abb. 3",
    Topic::ForcePlan,
);
pub(super) const N_RESOLVE_MEASURE: Note = note(
    "component read off at the force scale",
    Some("Komponente"),
    "LH A.2, Aufgabe 2",
    Topic::ForcePlan,
);
pub(super) const N_COMPONENT: Note = note(
    "component drawn",
    Some("Komponente"),
    "LH A.2",
    Topic::ForcePlan,
);
pub(super) const N_AUX_FORCE: Note = note(
    "force laid off at its point of application",
    Some("Parallelkraft"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX: Note = note(
    "auxiliary force P′ (and its opposite P″)",
    Some("Hilfskraft"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_PAR: Note = note(
    "parallelogram of the force and the auxiliary force",
    Some("Kräfteparallelogramm"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_R: Note = note(
    "line of action of the partial resultant",
    Some("Teilresultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_X: Note = note(
    "the partial resultants meet on the resultant",
    Some("Endresultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_LINE: Note = note(
    "the resultant, parallel to the forces",
    Some("Resultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_FOOT: Note = note(
    "the resultant cuts the line joining the points of application",
    Some("Hebelgesetz"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
pub(super) const N_AUX_A: Note = note(
    "distance a from the first point of application",
    Some("a : b = K2 : K1"),
    "LH C.1",
    Topic::Funicular,
);
