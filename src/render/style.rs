//! The textbook's hierarchy of lines and its lettering, as one stylesheet.

use crate::protocol::Role;

/// Margin around the figure (mm).
pub const MARGIN: f64 = 10.0;
/// Height of the title block above the figure (mm).
pub const TITLE_BLOCK: f64 = 22.0;
/// Height of one scale-bar row below the figure (mm).
pub const SCALE_ROW: f64 = 7.0;
/// Longest scale bar (mm); the bar shows the largest round quantity that fits.
pub const SCALE_BAR: f64 = 40.0;
/// Estimated advance of one character of the title (mm): used only to make the sheet wide
/// enough for its text. 0.57 em of its 6 mm: the bundled titles' DejaVu Serif averages
/// 0.54-0.55 em a character (measured from the font's advance widths), and a title must
/// never be cut off.
pub const TITLE_CHAR: f64 = 3.4;
/// Estimated advance of one character of a text line (mm), see [`TITLE_CHAR`]: 0.57 em of
/// its 3.5 mm (the sources' italic averages up to 0.55 em).
pub const TEXT_CHAR: f64 = 2.0;
/// Estimated advance of one character of small text (mm), see [`TITLE_CHAR`].
pub const SMALL_CHAR: f64 = 1.45;
/// Height of a table row (mm).
pub const TABLE_ROW: f64 = 3.6;
/// Space between table columns (mm).
pub const TABLE_GAP: f64 = 3.0;
/// Estimated advance of one character in a table (mm), a little wider than
/// [`SMALL_CHAR`] so that columns never touch.
pub const TABLE_CHAR: f64 = 1.7;
/// Advance of one character of a heading (a table of one cell: a load case's name), 4 mm
/// upright type (mm).
pub const HEADING_CHAR: f64 = 2.45;
/// Height of a heading's line (mm).
pub const HEADING_ROW: f64 = 5.0;
/// How far the drawn region reaches beyond the figure's solid parts, as a fraction of its
/// larger dimension: lines are clipped there.
pub const CLIP_REACH: f64 = 0.12;
/// How far a construction line runs past the last point constructed on it (mm).
pub const LINE_OVERSHOOT: f64 = 3.0;
/// Length of the short compass arc drawn through a point cut on a circle (mm of arc).
pub const COMPASS_ARC: f64 = 9.0;
/// Spacing and length of the hatching under a guide (mm).
pub const HATCH: f64 = 2.0;
/// Radius of the dot at a constructed point (mm).
pub const DOT: f64 = 0.3;
/// Offset of a label from its point (mm).
pub const LABEL_OFFSET: f64 = 1.6;
/// Height of a label's lettering on the sheet (mm: the font size of `text` in [`css`]), the
/// size the paper's reduction is held to ([`super::paper`]).
pub const LABEL_SIZE: f64 = 3.5;
/// Height of small text on the sheet (mm: `text.small` in [`css`]): the scale bars'
/// quantities and names, tables.
pub const SMALL_SIZE: f64 = 2.8;
/// Colour of the step shown last in a walk-through page.
pub const CURRENT: &str = "#b0362a";

/// The CSS class of a role.
pub fn class(role: Role) -> &'static str {
    match role {
        Role::Given => "given",
        Role::Axis => "axis",
        Role::Construction => "construction",
        Role::Auxiliary => "auxiliary",
        Role::Result => "result",
        Role::Force => "force",
        Role::Velocity => "velocity",
        Role::Guide => "guide",
        Role::Reduced => "reduced",
    }
}

/// The stylesheet. Stroke widths in mm of paper: 0.18 thin, 0.35 medium, 0.6 heavy, as a
/// drafter's pens; axes dash-dot, transfers dashed.
pub fn css() -> String {
    format!(
        "path,line,circle{{fill:none;stroke:#000;stroke-linecap:round}}\
.given{{stroke-width:0.35}}\
.axis{{stroke-width:0.18;stroke-dasharray:6 1.2 0.8 1.2}}\
.construction{{stroke-width:0.18}}\
.auxiliary{{stroke-width:0.18;stroke-dasharray:1.6 1}}\
.result{{stroke-width:0.6}}\
.force{{stroke-width:0.35;marker-end:url(#arrow)}}\
.velocity{{stroke-width:0.35;marker-end:url(#arrow-open)}}\
.guide{{stroke-width:0.6}}\
.reduced{{stroke-width:0.35;stroke-dasharray:3 1.2}}\
.hatch{{stroke-width:0.18}}\
.leader{{stroke-width:0.12}}\
circle.pt{{fill:#000;stroke:none}}\
.head{{fill:#000;stroke:none}}\
.head-open{{fill:none;stroke:#000;stroke-width:0.8}}\
text{{font-family:Times New Roman,Times,Liberation Serif,serif;font-style:italic;font-size:{label}px;fill:#000;stroke:none}}\
text.title{{font-style:normal;font-size:6px}}\
text.small{{font-style:normal;font-size:{small}px}}\
text.heading{{font-style:normal;font-size:4px}}\
.current path,.current line,.current circle{{stroke:{c}}}\
.current circle.pt,.current text{{fill:{c}}}",
        c = CURRENT,
        label = LABEL_SIZE,
        small = SMALL_SIZE,
    )
}

/// The text of a figure's `<style>` as a browser reads it (the writer puts the sheet on a
/// line of its own): what a page's Content-Security-Policy names by its hash.
pub fn style_text() -> String {
    format!("\n{}\n", css())
}

/// Most strokes of the hatching along one guide or support (beyond, the spacing grows).
pub const MAX_HATCH_STROKES: usize = 2000;
