//! The words of the truss construction's steps.

use crate::protocol::{note, Note, Topic};

pub(super) const N_JOINT: Note = note(
    "joint",
    Some("Knotenpunkt"),
    "LH B.4, Abb. 17",
    Topic::Truss,
);

pub(super) const N_MEMBER: Note = note("member", Some("Stab"), "LH B.4, Abb. 17", Topic::Truss);

pub(super) const N_SUPPORT: Note = note(
    "support reaction line",
    Some("Auflager"),
    "LH B.3",
    Topic::Truss,
);

pub(super) const N_LOAD: Note = note("joint load", Some("Knotenlast"), "LH B.3", Topic::Loads);

pub(super) const N_FP: Note = note(
    "loads laid off head to tail",
    Some("Krafteck"),
    "LH C.2",
    Topic::ForcePlan,
);

pub(super) const N_LOA: Note = note(
    "line of action of the load",
    Some("Wirkungslinie"),
    "LH C.2",
    Topic::Funicular,
);

pub(super) const N_B_CUT: Note = note(
    "last string cuts the reaction line of B",
    Some("Seileck"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_B_DIR: Note = note(
    "direction of B through the end of the loads",
    Some("Auflagerdruck B"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_SPLIT: Note = note(
    "the closing side divided into B and A",
    Some("Auflagerdrücke"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_REACT: Note = note(
    "support reaction read off",
    Some("Auflagerdruck"),
    "LH B.3, C.2",
    Topic::Reactions,
);

pub(super) const N_AXIS: Note = note(
    "reading direction",
    Some("Achse"),
    "LH B.3",
    Topic::Reactions,
);

pub(super) const N_EXT_DIR: Note = note(
    "direction of the external force through the last corner of the force polygon",
    Some("Krafteck der äußeren Kräfte"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);

pub(super) const N_EXT: Note = note(
    "external force laid on, clockwise round the truss",
    Some("Krafteck der äußeren Kräfte"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);

pub(super) const N_START: Note = note(
    "first space of the plan",
    Some("Kräfteplan"),
    "LH B.4",
    Topic::Cremona,
);

pub(super) const N_PAR: Note = note(
    "parallel to a member through the point of the space beyond it",
    Some("Parallele zum Stab"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);

pub(super) const N_SPACE: Note = note(
    "joint polygon closed: the two unknown member forces meet",
    Some("Knotenpunktpolygon"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);

pub(super) const N_SIDE: Note = note(
    "member force drawn: the side of the polygon between its two spaces",
    Some("Stabkraft"),
    "LH B.4, Abb. 17",
    Topic::Cremona,
);

pub(super) const N_FORCE: Note = note(
    "member force: tension if it points away from the joint (Regel 1)",
    Some("Stabkraft"),
    "LH B.4, Regel 1",
    Topic::Cremona,
);

pub(super) const N_BALANCE: Note = note(
    "the balance of every joint under the forces found: ΣX = ΣY = 0",
    Some("Gleichgewicht der Knotenpunkte"),
    "LH B.3",
    Topic::Cremona,
);

pub(super) const N_CASE_NAME: Note = note(
    "the load case’s name over its row",
    Some("Belastungsfall"),
    "LH B.4, Aufgabe 4",
    Topic::Cremona,
);
pub(super) const N_TABLE: Note = note(
    "table of member forces read off the plan",
    Some("Auswertung"),
    "LH B.4",
    Topic::Cremona,
);

pub(super) const N_POSITIONS: Note = note(
    "table of the moving load's positions: reactions, most loaded diagonal and vertical",
    Some("Tabelle der Laststellungen"),
    "LH B.4, Aufgabe 5, Tabelle 2",
    Topic::Cremona,
);

pub(super) const N_SLACK: Note = note(
    "counter-diagonal out of action in this case (flat bar, would be compressed)",
    Some("Gegendiagonale"),
    "LH B.5",
    Topic::Truss,
);

pub(super) const N_ZERO: Note = note(
    "zero-force member",
    Some("Nullstab"),
    "LH B.4, Aufgabe 5",
    Topic::Truss,
);

pub(super) const N_RESULTANT: Note = note(
    "the first and last strings meet on the resultant of the loads",
    Some("Resultierende"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_CULMANN_P: Note = note(
    "the resultant meets the lone roller’s line",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_CULMANN_Q: Note = note(
    "the other two reaction lines meet",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_CULMANN: Note = note(
    "Culmann’s line through both points",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);

pub(super) const N_CULMANN_PLAN: Note = note(
    "in the force plan: the lone reaction, then the two along Culmann’s line resolved",
    Some("Zerlegung"),
    "LH A.3, C.2",
    Topic::Reactions,
);

pub(super) const N_RITTER_CUT: Note = note(
    "Ritter section: the lines of two cut members meet in the moment point",
    Some("Rittersches Verfahren, Drehpunkt"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);

pub(super) const N_RITTER_PAR: Note = note(
    "the third cut member carried into the plan",
    Some("Rittersches Verfahren"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);

pub(super) const N_RITTER_FORCE: Note = note(
    "its force from the moment equation of the cut-off part, laid off at the force scale",
    Some("Momentengleichung"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);
