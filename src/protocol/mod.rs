//! The construction protocol: a board on which each kernel operation is recorded as a step
//! (number, kind, inputs, outputs, caption, German term, book reference, conditioning, checks),
//! after GeoGebra's construction protocol. The protocol is data: it serialises to JSON, and
//! every view (figure, check table, walk-through, benchmark) reads it.

mod accuracy;
mod board;
mod config;
mod error;
mod figure;
mod reference;
pub mod request;
mod step;
mod summary;
mod tracks;

pub use accuracy::{ErrorModel, WorstCut};
pub use board::{Board, CheckEntry, Cut, Reading, Scale, Trace, Turning, Weighted, H};
pub use config::{BoardConfig, Hand, Mode};
pub use error::{ConstructionError, CutOutcome};
pub use figure::{nice_at_least, FigureMeta, Paper, ScaleBar};
pub use reference::ReferenceRow;
pub use request::request_set;
pub use step::{
    note, Check, Drawn, Geom, Ids, Label, Mark, Note, ObjId, Object, Part, Role, Step, StepId,
    StepKind, Text, Topic, CROWD_LETTERED, TABLE_BLOCK_ROWS,
};
pub use summary::{CheckKind, CheckSummary, LISTED_CHECKS, LISTED_FAILURES};
