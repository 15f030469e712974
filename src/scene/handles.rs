//! What a student can drag in the browser page: the given points of a scene's figure and the
//! fields of the scene each one moves.
//!
//! A handle names a given point of the recorded board (a truss joint, a force's point of
//! application or the tail of its arrow, the pole O, a crank pin) and how a move of that
//! point on the sheet changes the scene: a position by the move over the length scale, an
//! angle by the turn about a centre. The page writes the new value into the scene's JSON and
//! replays the construction; the mechanics stay here and in the procedures, the page only
//! measures the pointer.

use super::{AnyScene, ForceSystemScene, SliderCrankScene, TrussScene};
use crate::protocol::{Board, Geom, Label, ObjId, Role};
use crate::statics::funicular::FORCE_LETTER;

/// A given point the page lets the student drag.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Handle {
    /// What it is, for the page's tooltip ("joint III", "crank pin at θ = 30°").
    pub name: String,
    /// The point dragged.
    #[serde(skip)]
    pub object: ObjId,
    /// What the drag changes.
    pub drag: Drag,
}

/// How a drag of a handle changes the scene.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Drag {
    /// A position `[x, y]` at the JSON pointer `field` moves with the point: by the point's
    /// move on the sheet (mm, y up) times `per_mm` (the scene's unit per mm of sheet).
    Point {
        /// The JSON pointer of the `[x, y]` pair (`/joints/2/at_m`).
        field: String,
        /// Its value now (given or chosen).
        value: [f64; 2],
        /// Scene units per mm of sheet.
        per_mm: f64,
    },
    /// An angle at the JSON pointer `field` (degrees): `zero_deg + sense · φ`, where φ is the
    /// direction of the point seen from the centre (sheet, y up, degrees), wrapped to
    /// [0, 360).
    Angle {
        /// The JSON pointer of the angle (`/forces/1/angle_deg`).
        field: String,
        /// The point the handle turns about.
        #[serde(skip)]
        center: ObjId,
        /// The angle when the point lies to the right of the centre.
        zero_deg: f64,
        /// +1 when the angle grows counter-clockwise on the sheet, −1 when clockwise.
        sense: f64,
    },
}

impl Handle {
    /// The other point the handle needs drawn positions of (an angle's centre).
    pub fn center(&self) -> Option<ObjId> {
        match self.drag {
            Drag::Angle { center, .. } => Some(center),
            Drag::Point { .. } => None,
        }
    }
}

/// The handles of `scene`'s construction on `board` (recorded from that scene): trusses'
/// joints, force systems' points of application, force directions and pole, slider-cranks'
/// crank pins at the angles a scene lists. Other procedures have none (their numbers move by
/// the scene's `preview.sliders`).
pub fn handles(scene: &AnyScene, board: &Board) -> Vec<Handle> {
    if let Some(t) = scene.get::<TrussScene>() {
        truss(t, scene, board)
    } else if let Some(f) = scene.get::<ForceSystemScene>() {
        force_system(f, scene, board)
    } else if let Some(c) = scene.get::<SliderCrankScene>() {
        slider_crank(c, board)
    } else {
        Vec::new()
    }
}

/// The given points of the board labelled `label`, in the order they were drawn.
fn given_points(board: &Board, label: Label) -> impl Iterator<Item = ObjId> + '_ {
    board.objects().iter().filter_map(move |o| {
        (o.role == Role::Given
            && matches!(o.geom, Geom::Point { .. })
            && o.label.base == label.base
            && o.label.index == label.index)
            .then_some(o.id)
    })
}

/// Every drawing of each joint (one per load case), moving the joint's `at_m`.
fn truss(t: &TrussScene, scene: &AnyScene, board: &Board) -> Vec<Handle> {
    let Some(p) = scene.problem().get::<TrussScene>() else {
        return Vec::new();
    };
    let per_mm = p.drawing.length_scale / 1000.0;
    let mut out = Vec::new();
    for (i, j) in t.joints.iter().enumerate() {
        let label = Label::from_name(&j.name);
        for object in given_points(board, label.clone()) {
            out.push(Handle {
                name: format!("joint {}", j.name),
                object,
                drag: Drag::Point {
                    field: format!("/joints/{i}/at_m"),
                    value: j.at_m,
                    per_mm,
                },
            });
        }
    }
    out
}

/// The points of application a₁, a₂, … (their `at_m`), the tails F₁, F₂, … of the force
/// arrows (their `angle_deg`, for forces given by magnitude and angle) and the pole O.
fn force_system(f: &ForceSystemScene, scene: &AnyScene, board: &Board) -> Vec<Handle> {
    let Some(p) = scene.problem().get::<ForceSystemScene>() else {
        return Vec::new();
    };
    let per_mm = p.drawing.length_scale / 1000.0;
    let mut out = Vec::new();
    for (i, force) in f.forces.iter().enumerate() {
        let k = i as u32 + 1;
        let Some(at) = given_points(board, Label::indexed("a", k)).next() else {
            continue;
        };
        out.push(Handle {
            name: format!("point of application of {FORCE_LETTER}{k}"),
            object: at,
            drag: Drag::Point {
                field: format!("/forces/{i}/at_m"),
                value: force.at_m,
                per_mm,
            },
        });
        if force.angle_deg.is_some() && force.kg.is_some() {
            if let Some(tail) = given_points(board, Label::indexed(FORCE_LETTER, k)).next() {
                // The arrow runs from its tail to the point of application: the force's angle
                // is the direction of the centre seen from the tail, φ + 180°.
                out.push(Handle {
                    name: format!("direction of {FORCE_LETTER}{k}"),
                    object: tail,
                    drag: Drag::Angle {
                        field: format!("/forces/{i}/angle_deg"),
                        center: at,
                        zero_deg: 180.0,
                        sense: 1.0,
                    },
                });
            }
        }
    }
    out.extend(pole(board, p.drawing.force_scale));
    out
}

/// The pole O, moving `drawing.pole_kg` (kg from the force polygon's first corner, which
/// the first pole ray's step names as its second input).
fn pole(board: &Board, force_scale: f64) -> Option<Handle> {
    let o = given_points(board, Label::plain("O")).next()?;
    let ray = (board.steps().iter()).find(|s| s.inputs.len() == 2 && s.inputs[0] == o)?;
    let point = |id: ObjId| match board.object(id).map(|x| &x.geom) {
        Some(Geom::Point { at }) => Some(*at),
        _ => None,
    };
    let (pole, first) = (point(o)?, point(ray.inputs[1])?);
    let kg = (pole - first) * force_scale;
    Some(Handle {
        name: "pole O".into(),
        object: o,
        drag: Drag::Point {
            field: "/drawing/pole_kg".into(),
            value: [kg.x, kg.y],
            per_mm: force_scale,
        },
    })
}

/// The crank pins A₀, A₁, … at the angles a scene lists: θ from the inner dead centre, left
/// of the shaft centre O, turning clockwise on the sheet (LH Abb. 45): θ = 180° − φ.
fn slider_crank(c: &SliderCrankScene, board: &Board) -> Vec<Handle> {
    let super::AngleSpec::Degrees(thetas) = &c.angles else {
        return Vec::new();
    };
    let Some(center) = given_points(board, Label::plain("O")).next() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (k, theta) in thetas.iter().enumerate() {
        let label = Label::indexed("A", k as u32);
        if let Some(pin) = given_points(board, label.clone()).next() {
            out.push(Handle {
                name: format!("crank pin at θ = {}°", crate::fmt::num(*theta, 2)),
                object: pin,
                drag: Drag::Angle {
                    field: format!("/angles/degrees/{k}"),
                    center,
                    zero_deg: 180.0,
                    sense: -1.0,
                },
            });
        }
    }
    out
}
