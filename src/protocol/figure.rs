//! What a sheet writes besides the construction: the title, the book reference and the scale
//! bars. Data only: a procedure fills it in, the renderer draws it.

use crate::fmt::num;
use crate::kernel::tolerance::NICE_SCALE_SLACK;

/// A scale bar written under the figure: `per_mm` quantity units per mm of sheet.
///
/// The constructors write the books' German names:
///
/// ```
/// use graphostatik::protocol::ScaleBar;
/// let bar = ScaleBar::force(100.0); // LH Aufgabe 1: 1 mm = 100 kg
/// assert_eq!(bar.name, "Kräftemaßstab 1 mm = 100 kg");
/// assert_eq!(ScaleBar::length(50.0, "m").per_mm, 0.05); // 1 : 50, read in metres
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ScaleBar {
    /// Name written before the bar ("Längenmaßstab 1 : 10").
    pub name: String,
    /// Quantity per mm of sheet.
    pub per_mm: f64,
    /// Unit written at the bar's end ("mm", "kg", "m/s").
    pub unit: String,
}

impl ScaleBar {
    /// Längenmaßstab 1 : n, the bar read in `unit` (`"m"` or `"mm"` of the machine).
    pub fn length(n: f64, unit: &str) -> ScaleBar {
        let per_mm = if unit == "m" { n / 1000.0 } else { n };
        ScaleBar {
            name: format!("Längenmaßstab 1 : {}", crate::fmt::book_number(n, 3)),
            per_mm,
            unit: unit.into(),
        }
    }

    /// Kräftemaßstab 1 mm = f kg.
    pub fn force(f: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Kräftemaßstab 1 mm = {} kg", num(f, 6)),
            per_mm: f,
            unit: "kg".into(),
        }
    }

    /// Momentenmaßstab 1 mm = m kg·m.
    pub fn moment(m: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Momentenmaßstab 1 mm = {} kg·m", num(m, 6)),
            per_mm: m,
            unit: "kg·m".into(),
        }
    }

    /// Flächenmaßstab 1 mm = a m².
    pub fn area(a: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Flächenmaßstab 1 mm = {} m²", num(a, 6)),
            per_mm: a,
            unit: "m²".into(),
        }
    }

    /// Beschleunigungsmaßstab 1 mm = b m/s² (LH Abb. 55: 1 cm = 150 m/s²).
    pub fn acceleration(b: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Beschleunigungsmaßstab 1 mm = {} m/s²", num(b, 6)),
            per_mm: b,
            unit: "m/s²".into(),
        }
    }

    /// Geschwindigkeitsmaßstab 1 mm = v m/s.
    pub fn velocity(v: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Geschwindigkeitsmaßstab 1 mm = {} m/s", num(v, 6)),
            per_mm: v,
            unit: "m/s".into(),
        }
    }
}

/// What the sheet says besides the construction: title, source, scales.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FigureMeta {
    /// The title.
    pub title: String,
    /// The book reference.
    pub source: String,
    /// The scale bars.
    pub scales: Vec<ScaleBar>,
    /// What the book's plate letters, each as a scene writes a name (`P1` for P₁, `II`,
    /// `+`): the figure test holds that the figure writes every one
    /// ([`FigureReport::unnamed`](crate::render::FigureReport::unnamed)).
    pub plate: Vec<String>,
}

impl FigureMeta {
    /// A sheet with a title and nothing else yet.
    pub fn titled(title: impl Into<String>) -> FigureMeta {
        FigureMeta {
            title: title.into(),
            ..FigureMeta::default()
        }
    }

    /// Sets the book reference written under the title.
    pub fn source(mut self, source: impl Into<String>) -> FigureMeta {
        self.source = source.into();
        self
    }

    /// Adds a scale bar.
    pub fn scale(mut self, bar: ScaleBar) -> FigureMeta {
        self.scales.push(bar);
        self
    }
}

/// The paper a figure is set on (`render --paper`, a scene's `paper` field): an A-series
/// sheet (ISO 216), turned portrait or landscape whichever takes the figure at the smaller
/// reduction, or `fit`, the figure's own size (the default: a sheet exactly as large as its
/// drawing, at 1 : 1).
///
/// ```
/// use graphostatik::protocol::Paper;
/// assert_eq!(Paper::A4.size_mm(), Some([210.0, 297.0]));
/// assert_eq!(Paper::A3.larger(), Some(Paper::A2));
/// assert_eq!(Paper::parse("a1"), Some(Paper::A1));
/// assert_eq!(Paper::parse("A5"), None);
/// ```
#[derive(
    Debug,
    Clone,
    Copy,
    PartialEq,
    Eq,
    PartialOrd,
    Ord,
    Default,
    serde::Serialize,
    serde::Deserialize,
)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum Paper {
    /// The figure's own size, at 1 : 1 (the default).
    #[default]
    Fit,
    /// A4, 210 × 297 mm.
    A4,
    /// A3, 297 × 420 mm.
    A3,
    /// A2, 420 × 594 mm.
    A2,
    /// A1, 594 × 841 mm: the largest a figure is set on; a figure too large for it at the
    /// smallest lettering allowed is split into pages.
    A1,
}

impl Paper {
    /// The names a scene or `--paper` gives, in the order of [`Paper::parse`]'s list.
    pub const NAMES: &'static [&'static str] = &["fit", "a4", "a3", "a2", "a1"];

    /// The paper named `name` (`"a4"`, `"A4"`, `"fit"`), or `None`.
    pub fn parse(name: &str) -> Option<Paper> {
        match name.to_ascii_lowercase().as_str() {
            "fit" => Some(Paper::Fit),
            "a4" => Some(Paper::A4),
            "a3" => Some(Paper::A3),
            "a2" => Some(Paper::A2),
            "a1" => Some(Paper::A1),
            _ => None,
        }
    }

    /// Width and height of the sheet upright (mm, ISO 216); `None` for [`Paper::Fit`].
    pub fn size_mm(self) -> Option<[f64; 2]> {
        match self {
            Paper::Fit => None,
            Paper::A4 => Some([210.0, 297.0]),
            Paper::A3 => Some([297.0, 420.0]),
            Paper::A2 => Some([420.0, 594.0]),
            Paper::A1 => Some([594.0, 841.0]),
        }
    }

    /// The next larger A-series sheet, up to [`Paper::A1`]; `None` past it and for `Fit`.
    pub fn larger(self) -> Option<Paper> {
        match self {
            Paper::A4 => Some(Paper::A3),
            Paper::A3 => Some(Paper::A2),
            Paper::A2 => Some(Paper::A1),
            Paper::A1 | Paper::Fit => None,
        }
    }

    /// The name as a sheet writes it: `A4`, `fit`.
    pub fn name(self) -> &'static str {
        match self {
            Paper::Fit => "fit",
            Paper::A4 => "A4",
            Paper::A3 => "A3",
            Paper::A2 => "A2",
            Paper::A1 => "A1",
        }
    }
}

/// The next "nice" scale (1, 2, 2.5, 5 × 10ᵏ) at or above `x`: how a drafter picks a scale
/// for a figure of a wanted size. A non-positive or non-finite `x` gives 1.
///
/// ```
/// use graphostatik::protocol::nice_at_least;
/// assert_eq!(nice_at_least(13.0), 20.0);
/// assert_eq!(nice_at_least(0.3), 0.5);
/// assert_eq!(nice_at_least(250.0), 250.0);
/// ```
pub fn nice_at_least(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let k = x.log10().floor();
    let base = 10f64.powf(k);
    for m in [1.0, 2.0, 2.5, 5.0, 10.0] {
        if m * base >= x * (1.0 - NICE_SCALE_SLACK) {
            return m * base;
        }
    }
    10.0 * base
}
