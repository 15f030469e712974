//! Rendering: textbook-style SVG with one Inkscape layer per construction step, walk-through
//! pages, and the check table. The renderer reads a recorded [`Board`](crate::protocol::Board)
//! and computes no mechanics: the scales and title it writes come in a [`FigureMeta`].

mod book;
mod csp;
mod drafting;
#[cfg(feature = "export")]
pub mod export;
mod extent;
mod figure;
pub mod forces;
mod ink;
mod labels;
pub mod layout;
pub mod paper;
mod plot;
mod style;
mod table;
mod walkthrough;
mod xml;

pub use crate::protocol::{FigureMeta, ScaleBar};
pub use book::{book_rows, book_table_text, BookRow, Verdict};
pub use csp::{content_security_policy, with_policy, Allow};
pub use drafting::drafting_table_text;
pub use figure::{
    figure, figure_held, figure_lettered, figure_with_points, inspect, FigureReport, Layout,
    Lettering,
};
pub use plot::{accuracy_plot_svg, accuracy_table_text};
pub use table::{
    check_rows, check_table_json, check_table_text, reference_rows, reference_table_json,
    reference_table_text, summary_json, CheckRow, KindJson, ReferenceTableRow, SummaryJson,
};
pub use walkthrough::{
    html_text, list_lines, page_count, page_details, page_ranges, step_names, walkthrough,
    walkthrough_details, walkthrough_html, walkthrough_item, walkthrough_item_list,
    walkthrough_items, walkthrough_lines, walkthrough_list, walkthrough_page, Grouping, Page,
    StepList, WalkOptions,
};
