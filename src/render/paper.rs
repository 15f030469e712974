//! Sheets that fit a page: a figure set on A-series paper (`render --paper`, a scene's
//! `paper` field).
//!
//! A figure's sheet is as large as its drawing (`fit`, the default). On paper, the whole
//! sheet (title, drawing, scale bars) is reduced at a stated scale from [`REDUCTIONS`] (a
//! sheet of 1 : 1.25 is drawn four fifths of its size) and centred within the paper's
//! margins, turned portrait or landscape whichever takes it at the smaller reduction. A
//! reduction is allowed only where a label's lettering ([`LABEL_SIZE`], 3.5 mm on the sheet)
//! stays at least [`MIN_LETTERING`] high on paper: at most 1 : 1.4.
//!
//! The scale bars are reduced with the drawing, so each still measures the drawing true (a
//! bar of 2 m is as long as 2 m of the reduced drawing); the names written before them are
//! restated for the page (`Längenmaßstab 1 : 50` of the sheet is `1 : 62½` at 1 : 1.25,
//! `Kräftemaßstab 1 mm = 100 kg` is `1 mm = 125 kg`), and a line under the sheet says the
//! paper and the reduction.
//!
//! A figure that does not fit the paper asked for is split into pages the book's way: a row
//! of parts to a page, in order, never through a part (LH Aufgabe 5: a load case to a page,
//! the table of every crane position on its own), all at one reduction. Where even one row does not fit, the next larger paper
//! is tried, up to A1; past A1 the figure is drawn at its own size. What was done instead of
//! what was asked is said in one line ([`OnPaper::said`]).

use super::figure::{figure_lettered, Lettering};
use super::style::{LABEL_SIZE, SMALL_CHAR, SMALL_SIZE};
use super::xml::escaped;
use crate::fmt::{book_number, num};
use crate::protocol::{Board, FigureMeta, Paper, ScaleBar};

/// The paper's blank margin on every side (mm): what a printer leaves unprinted.
pub const PAPER_MARGIN: f64 = 10.0;
/// The least height of lettering on paper (mm), ISO 3098's smallest.
pub const MIN_LETTERING: f64 = 2.5;
/// The reductions a sheet is set at (1 : r), the preferred numbers of the R40 series from 1
/// to 1.4: a label's 3.5 mm is 2.5 mm at 1 : 1.4. The least that fits is taken.
pub const REDUCTIONS: [f64; 7] = [1.0, 1.06, 1.12, 1.18, 1.25, 1.32, 1.4];
/// The row under the reduced sheet that says the paper and the reduction (mm of paper).
pub const NOTE_ROW: f64 = 5.0;
/// How far a reduced sheet may pass the paper's area and still fit (mm): the sheet's sizes
/// are written to 0.001 mm.
const FIT_SLACK: f64 = 1e-6;
/// How far lettering may fall short of [`MIN_LETTERING`] by rounding alone (mm): 3.5 / 1.4
/// is 2.5 in exact arithmetic.
const LETTERING_SLACK: f64 = 1e-9;

/// Where a sheet stands on paper: the paper, turned, and the reduction 1 : `reduction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// The A-series paper.
    pub paper: Paper,
    /// Whether it is turned landscape (long side across).
    pub landscape: bool,
    /// The reduction: the sheet is drawn at 1 / `reduction` of its size.
    pub reduction: f64,
}

impl Placement {
    /// Width and height of the page (mm).
    pub fn page_mm(&self) -> [f64; 2] {
        let [w, h] = self.paper.size_mm().unwrap_or([0.0, 0.0]);
        if self.landscape {
            [h, w]
        } else {
            [w, h]
        }
    }
    /// The height of a label's lettering on paper (mm).
    pub fn lettering_mm(&self) -> f64 {
        LABEL_SIZE / self.reduction
    }
    /// How the page names itself: `A4 landscape`.
    pub fn name(&self) -> String {
        let turn = if self.landscape {
            "landscape"
        } else {
            "portrait"
        };
        format!("{} {turn}", self.paper.name())
    }
}

/// The reductions that keep a label at least [`MIN_LETTERING`] high.
fn allowed() -> impl Iterator<Item = f64> {
    (REDUCTIONS.into_iter()).filter(|r| LABEL_SIZE / r >= MIN_LETTERING - LETTERING_SLACK)
}

/// Where a sheet `sheet` (width, height, mm) stands on `paper`: the least allowed reduction
/// of at least `at_least` at which it fits within the margins with the note row under it,
/// turned the way its longer side goes where both ways take it; `None` where none fits (or
/// the paper is `fit`).
///
/// ```
/// use graphostatik::protocol::Paper;
/// use graphostatik::render::paper::place;
/// // LH Abb. 24's 259.5 × 295.7 mm sheet: on A4 at 1 : 1.4, portrait; A3 takes it whole.
/// let a4 = place([259.5, 295.7], Paper::A4, 1.0).unwrap();
/// assert_eq!((a4.reduction, a4.landscape), (1.4, false));
/// assert_eq!(place([259.5, 295.7], Paper::A3, 1.0).unwrap().reduction, 1.0);
/// // The crane bridge's 1116 × 816 mm: not on A1 with 2.5 mm lettering.
/// assert_eq!(place([1116.1, 816.2], Paper::A1, 1.0), None);
/// ```
pub fn place(sheet: [f64; 2], paper: Paper, at_least: f64) -> Option<Placement> {
    let [pw, ph] = paper.size_mm()?;
    let [w, h] = sheet;
    if !(w.is_finite() && h.is_finite()) {
        return None;
    }
    let fits = |r: f64, landscape: bool| {
        let [aw, ah] = if landscape { [ph, pw] } else { [pw, ph] };
        w / r <= aw - 2.0 * PAPER_MARGIN + FIT_SLACK
            && h / r + NOTE_ROW <= ah - 2.0 * PAPER_MARGIN + FIT_SLACK
    };
    let wide = w > h;
    (allowed().filter(|&r| r >= at_least)).find_map(|reduction| {
        ([wide, !wide].into_iter().find(|&l| fits(reduction, l))).map(|landscape| Placement {
            paper,
            landscape,
            reduction,
        })
    })
}

/// The name of scale bar `bar` restated for its sheet reduced 1 : `r`: `Längenmaßstab 1 : 50`
/// at 1 : 1.25 is `Längenmaßstab 1 : 62½`, `Kräftemaßstab 1 mm = 100 kg` is
/// `Kräftemaßstab 1 mm = 125 kg`; a name of another form gets the reduction after it.
///
/// ```
/// use graphostatik::protocol::ScaleBar;
/// use graphostatik::render::paper::restated;
/// assert_eq!(restated(&ScaleBar::length(50.0, "m"), 1.25), "Längenmaßstab 1 : 62½");
/// assert_eq!(restated(&ScaleBar::force(100.0), 1.25), "Kräftemaßstab 1 mm = 125 kg");
/// assert_eq!(restated(&ScaleBar::force(100.0), 1.0), "Kräftemaßstab 1 mm = 100 kg");
/// ```
pub fn restated(bar: &ScaleBar, r: f64) -> String {
    if r == 1.0 {
        return bar.name.clone();
    }
    if let Some((head, _)) = bar.name.split_once(" 1 : ") {
        let n = if bar.unit == "m" {
            bar.per_mm * 1000.0
        } else {
            bar.per_mm
        };
        return format!("{head} 1 : {}", book_number(n * r, 3));
    }
    if let Some((head, _)) = bar.name.split_once(" 1 mm = ") {
        return format!("{head} 1 mm = {} {}", num(bar.per_mm * r, 6), bar.unit);
    }
    format!("{} (reduced 1 : {})", bar.name, num(r, 2))
}

/// `meta` as the page writes it: the scale bars' names restated for the reduction `r`, and
/// the page's number in the title where the figure is split (`page` of `pages`).
fn page_meta(meta: &FigureMeta, r: f64, page: Option<(usize, usize)>) -> FigureMeta {
    let mut m = meta.clone();
    for s in &mut m.scales {
        s.name = restated(s, r);
    }
    if let Some((i, n)) = page {
        m.title = format!("{} (page {i} of {n})", meta.title);
    }
    m
}

/// One page of a figure on paper: its SVG, and where its sheet stands (`None`: drawn at its
/// own size, as `fit`).
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    /// The page's SVG: its width and height those of the paper, in mm.
    pub svg: String,
    /// The paper, its turn and the reduction.
    pub at: Option<Placement>,
}

/// A figure set on paper: one page or several, how its lettering went (summed over the
/// pages), and what was done instead of what was asked, if anything.
#[derive(Debug, Clone, PartialEq)]
pub struct OnPaper {
    /// The pages in order.
    pub pages: Vec<Page>,
    /// The labels written and left out, over every page.
    pub lettering: Lettering,
    /// One line where the figure did not go on one sheet of the paper asked for: `A4 too
    /// small for 2.5 mm lettering, set on A2`, split into pages, or drawn at its own size.
    pub said: Option<String>,
}

/// A sheet drawn for a paper: its SVG at the sheet's size, its lettering, its placement.
struct Set {
    svg: String,
    lettering: Lettering,
    at: Placement,
}

/// The figure of `board` set on `paper` (`fit`: the figure as [`figure_lettered`] draws it,
/// one page at its own size): whole on the paper where it fits with lettering of at least
/// [`MIN_LETTERING`], else split into pages by rows of parts, else on the next larger paper,
/// up to A1, else at its own size. Deterministic, and bounded: at most a page per row of
/// parts, and at most a few drawings per paper of the board's own parts.
pub fn on_paper(meta: &FigureMeta, board: &Board, paper: Paper) -> OnPaper {
    let (svg, lettering) = figure_lettered(meta, board, None);
    let size = sheet_size(&svg);
    let rows = drawn_rows(board);
    let mut next = paper.size_mm().map(|_| paper);
    while let Some(at) = next {
        let whole = place(size, at, 1.0).and_then(|p| set(meta, board, at, p.reduction, None));
        if let Some(s) = whole {
            let said = (at != paper).then(|| {
                format!(
                    "{} too small for {MIN_LETTERING} mm lettering, set on {}",
                    paper.name(),
                    at.name()
                )
            });
            return pages_of(vec![s], said);
        }
        if let Some(sets) = (rows.len() > 1)
            .then(|| paged(meta, board, at, &rows))
            .flatten()
        {
            let n = sets.len();
            let said = match at == paper {
                true => format!(
                    "too large for one {} sheet with {MIN_LETTERING} mm lettering, split into {n} pages",
                    paper.name()
                ),
                false => format!(
                    "{} too small for {MIN_LETTERING} mm lettering, split into {n} pages of {}",
                    paper.name(),
                    at.name()
                ),
            };
            return pages_of(sets, Some(said));
        }
        next = at.larger();
    }
    let said = paper.size_mm().map(|_| {
        format!(
            "too large for A1 with {MIN_LETTERING} mm lettering, drawn at its own size, {} × {} mm",
            num(size[0], 0),
            num(size[1], 0)
        )
    });
    OnPaper {
        pages: vec![Page { svg, at: None }],
        lettering,
        said,
    }
}

/// The sets made pages, numbered where there are several.
fn pages_of(sets: Vec<Set>, said: Option<String>) -> OnPaper {
    let n = sets.len();
    let mut lettering = Lettering::default();
    let pages = (sets.into_iter().enumerate())
        .map(|(i, s)| {
            lettering.labels += s.lettering.labels;
            lettering.left_out += s.lettering.left_out;
            lettering.withheld += s.lettering.withheld;
            let page = (n > 1).then_some((i + 1, n));
            Page {
                svg: page_svg(&s.svg, &s.at, page),
                at: Some(s.at),
            }
        })
        .collect();
    OnPaper {
        pages,
        lettering,
        said,
    }
}

/// The sheet of `board` drawn for `paper` at a reduction of at least `from`, its scale
/// names restated for the reduction it is set at: the names can widen the sheet, so it is
/// drawn again until the reduction holds (at most once per reduction, which only grows).
fn set(
    meta: &FigureMeta,
    board: &Board,
    paper: Paper,
    from: f64,
    page: Option<(usize, usize)>,
) -> Option<Set> {
    let mut r = from;
    for _ in 0..REDUCTIONS.len() {
        let (svg, lettering) = figure_lettered(&page_meta(meta, r, page), board, None);
        let at = place(sheet_size(&svg), paper, r)?;
        if at.reduction == r {
            return Some(Set { svg, lettering, at });
        }
        r = at.reduction;
    }
    None
}

/// The rows of parts `board` draws in, top to bottom.
fn drawn_rows(board: &Board) -> Vec<u16> {
    let rows: std::collections::BTreeSet<u16> = (board.drawn_objects())
        .filter_map(|o| board.step(o.step))
        .map(|s| s.part.row)
        .collect();
    rows.into_iter().collect()
}

/// `board` with only the rows `rows` drawn.
fn rows_of(board: &Board, rows: &[u16]) -> Board {
    let mut b = board.clone();
    b.show_only(|p| rows.contains(&p.row));
    b
}

/// The figure split into pages on `paper` the book's way: a row of parts to a page, in
/// order (LH Aufgabe 5: a load case to a page, the table of every crane position on its
/// own), every page drawn at the largest reduction any of them needs; `None` where a row
/// does not fit.
fn paged(meta: &FigureMeta, board: &Board, paper: Paper, rows: &[u16]) -> Option<Vec<Set>> {
    let n = rows.len();
    let mut r = 1.0;
    for _ in 0..REDUCTIONS.len() {
        // Each page's board made as it is drawn: one copy of the board at a time.
        let sets = (rows.iter().enumerate())
            .map(|(i, row)| {
                let b = rows_of(board, std::slice::from_ref(row));
                set(meta, &b, paper, r, Some((i + 1, n)))
            })
            .collect::<Option<Vec<Set>>>()?;
        let most = sets.iter().map(|s| s.at.reduction).fold(1.0, f64::max);
        if sets.iter().all(|s| s.at.reduction == most) {
            return Some(sets);
        }
        r = most;
    }
    None
}

/// The value of attribute `name` in the root tag of `svg`.
fn root_attr<'a>(svg: &'a str, name: &str) -> Option<&'a str> {
    let tag = &svg[..svg.find('>')?];
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    let len = tag[at..].find('"')?;
    Some(&tag[at..at + len])
}

/// A sheet's width and height (mm), read from its SVG.
pub fn sheet_size(svg: &str) -> [f64; 2] {
    let mm = |name| {
        root_attr(svg, name)
            .and_then(|v| v.strip_suffix("mm"))
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(f64::NAN)
    };
    [mm("width"), mm("height")]
}

/// The page: the sheet `svg` reduced and centred within the margins with the note row under
/// it, its style and markers kept, every layer of it inside one layer of the page.
fn page_svg(svg: &str, at: &Placement, page: Option<(usize, usize)>) -> String {
    let [pw, ph] = at.page_mm();
    let [w, h] = sheet_size(svg);
    let view: Vec<f64> = (root_attr(svg, "viewBox").unwrap_or("0 0 0 0").split(' '))
        .map(|v| v.parse().unwrap_or(0.0))
        .collect();
    let k = 1.0 / at.reduction;
    let (ox, oy) = ((pw - w * k) / 2.0, (ph - h * k - NOTE_ROW) / 2.0);
    let body_at = svg.find('>').map_or(0, |i| i + 1);
    let rest = &svg[body_at..];
    let (head, body) = rest.split_at(rest.find("<g id=\"sheet\"").unwrap_or(0));
    let body = body.trim_end().strip_suffix("</svg>").unwrap_or(body);
    let mut note = format!(
        "{}, the sheet at 1 : {}, lettering {} mm; the scales are stated for this page",
        at.name(),
        num(at.reduction, 2),
        num(at.lettering_mm(), 1)
    );
    if let Some((i, n)) = page {
        note.push_str(&format!("; page {i} of {n}"));
    }
    let note_w = note.chars().count() as f64 * SMALL_CHAR;
    let note_x = (ox + super::style::MARGIN * k).min(pw - PAPER_MARGIN - note_w);
    let mut out = format!(
        "<svg height=\"{h}mm\" viewBox=\"0 0 {w} {h}\" width=\"{w}mm\" \
         xmlns=\"http://www.w3.org/2000/svg\" \
         xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\">",
        w = num(pw, 3),
        h = num(ph, 3)
    );
    out.push_str(head);
    out.push_str(&format!(
        "<g id=\"paper-sheet\" inkscape:groupmode=\"layer\" inkscape:label=\"the sheet at 1 : {}\" \
         transform=\"translate({},{}) scale({}) translate({},{})\">\n",
        num(at.reduction, 2),
        num(ox, 3),
        num(oy, 3),
        num(k, 6),
        num(-view.first().copied().unwrap_or(0.0), 3),
        num(-view.get(1).copied().unwrap_or(0.0), 3),
    ));
    out.push_str(body);
    out.push_str(&format!(
        "</g>\n<g id=\"paper\" inkscape:groupmode=\"layer\" inkscape:label=\"paper\">\n\
         <text class=\"small\" x=\"{}\" y=\"{}\">",
        num(note_x.max(PAPER_MARGIN), 3),
        num(oy + h * k + NOTE_ROW - 1.0, 3)
    ));
    escaped(&mut out, &note);
    out.push_str("</text>\n</g>\n</svg>\n");
    out
}

/// The smallest lettering of a page on paper (mm): the sheet's small text (scale bars,
/// tables) reduced as the labels are.
pub fn small_mm(at: &Placement) -> f64 {
    SMALL_SIZE / at.reduction
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::protocol::{Note, Part, Role, Topic};

    /// Every reduction a sheet is set at keeps a label at least 2.5 mm high, and 1 : 1.4,
    /// the last, is the one that leaves it exactly so.
    #[test]
    fn every_allowed_reduction_keeps_lettering_of_2_5_mm() {
        let allowed: Vec<f64> = allowed().collect();
        assert_eq!(allowed, REDUCTIONS);
        for r in allowed {
            assert!(LABEL_SIZE / r >= MIN_LETTERING - LETTERING_SLACK, "1 : {r}");
        }
        let just_past: f64 = 1.41;
        assert!(LABEL_SIZE / just_past < MIN_LETTERING);
    }

    /// The paper is turned the way that takes the sheet at the smaller reduction; of two
    /// that take it alike, the way its longer side goes; and the least reduction is taken.
    #[test]
    fn the_paper_is_turned_and_the_least_reduction_taken() {
        // 250 × 150 mm: landscape on A4 at 1 : 1 (277 × 190 within the margins).
        let p = place([250.0, 150.0], Paper::A4, 1.0).unwrap();
        assert_eq!(
            (p.landscape, p.reduction, p.page_mm()),
            (true, 1.0, [297.0, 210.0])
        );
        // 150 × 250: portrait.
        let p = place([150.0, 250.0], Paper::A4, 1.0).unwrap();
        assert_eq!((p.landscape, p.reduction), (false, 1.0));
        // 300 × 200: 1 : 1.12 landscape (300 / 1.12 = 268 ≤ 277, 200 / 1.12 + 5 ≤ 190).
        let p = place([300.0, 200.0], Paper::A4, 1.0).unwrap();
        assert_eq!((p.landscape, p.reduction), (true, 1.12));
        assert!((p.lettering_mm() - 3.125).abs() < 1e-9);
        // Asked for at least 1 : 1.25, it is set so even where less would do.
        assert_eq!(
            place([150.0, 150.0], Paper::A4, 1.25).unwrap().reduction,
            1.25
        );
        // Too large at 1 : 1.4 (277 × 1.4 = 387.8 mm), or not a number: no place.
        assert_eq!(place([390.0, 100.0], Paper::A4, 1.0), None);
        assert_eq!(place([f64::NAN, 100.0], Paper::A4, 1.0), None);
        assert_eq!(place([100.0, 100.0], Paper::Fit, 1.0), None);
    }

    /// A length scale and the quantity scales restated for the reduced sheet: the bar's
    /// quantity per mm of paper is the sheet's times the reduction.
    #[test]
    fn scale_names_are_restated_for_the_page() {
        assert_eq!(
            restated(&ScaleBar::length(50.0, "m"), 1.4),
            "Längenmaßstab 1 : 70"
        );
        assert_eq!(
            restated(&ScaleBar::length(2.0, "mm"), 1.25),
            "Längenmaßstab 1 : 2½"
        );
        assert_eq!(
            restated(&ScaleBar::moment(75.0), 1.12),
            "Momentenmaßstab 1 mm = 84 kg·m"
        );
        let odd = ScaleBar {
            name: "Zeit".into(),
            per_mm: 1.0,
            unit: "s".into(),
        };
        assert_eq!(restated(&odd, 1.25), "Zeit (reduced 1 : 1.25)");
    }

    fn two_rows(wide_mm: f64, high_mm: f64) -> Board {
        let mut b = Board::recording();
        let n = || Note::new("given", Topic::Custom("demo"));
        b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n());
        b.point(Point::new(wide_mm, high_mm), Role::Given.named("B"), n());
        b.set_part(Part::at(1, 0));
        b.point(Point::new(0.0, 0.0), Role::Given.named("C"), n());
        b.point(Point::new(wide_mm, high_mm), Role::Given.named("D"), n());
        b
    }

    /// `fit` is the figure as drawn, byte for byte; on A4 the page is A4 and says its
    /// reduction; too large for A4 whole, it is split by its rows; too large for A1 even
    /// so, it is drawn at its own size and said so.
    #[test]
    fn a_figure_is_set_whole_split_by_rows_or_left_at_its_own_size() {
        let meta = FigureMeta::titled("Two rows").scale(ScaleBar::force(10.0));
        let board = two_rows(100.0, 40.0);
        let fit = on_paper(&meta, &board, Paper::Fit);
        assert_eq!(fit.pages[0].svg, crate::render::figure(&meta, &board, None));
        assert_eq!((fit.pages[0].at, &fit.said), (None, &None));
        let a4 = on_paper(&meta, &board, Paper::A4);
        assert_eq!((a4.pages.len(), &a4.said), (1, &None));
        let at = a4.pages[0].at.unwrap();
        let [w, h] = at.page_mm();
        assert_eq!(sheet_size(&a4.pages[0].svg), [w, h]);
        assert!(a4.pages[0]
            .svg
            .contains(&format!("{}, the sheet at 1 : ", at.name())));
        // 700 mm wide: neither whole nor a row fits A4 or A3; A2 takes it whole.
        let a4 = on_paper(&meta, &two_rows(700.0, 40.0), Paper::A4);
        assert_eq!(a4.pages[0].at.unwrap().paper, Paper::A2);
        let said = a4.said.unwrap();
        assert!(
            said.starts_with("A4 too small for 2.5 mm lettering, set on A2"),
            "{said}"
        );
        // Two rows of 300 × 120 mm: each fits A4, both together not.
        let split = on_paper(&meta, &two_rows(300.0, 120.0), Paper::A4);
        assert_eq!(split.pages.len(), 2, "{:?}", split.said);
        assert!(split.pages[0].svg.contains("(page 1 of 2)"));
        assert!(split.said.unwrap().contains("split into 2 pages"));
        let own = on_paper(&meta, &two_rows(2000.0, 40.0), Paper::A4);
        assert_eq!(own.pages[0].at, None);
        assert!(own.said.unwrap().starts_with("too large for A1"));
    }
}
