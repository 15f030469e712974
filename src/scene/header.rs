//! The header every scene starts with (`procedure`, `title`, `source`, `notes`), declared once.

/// Declares a scene struct: the header fields first (`procedure`, `title`, `source`, `notes`),
/// then the procedure's own fields; derives serde (unknown fields rejected), the JSON Schema,
/// and [`SceneHeader`](crate::scene::SceneHeader).
macro_rules! scene_struct {
    (
        $(#[$m:meta])*
        pub struct $name:ident {
            $($(#[$fm:meta])* pub $field:ident : $ty:ty),* $(,)?
        }
    ) => {
        $(#[$m])*
        #[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
        #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
        #[serde(deny_unknown_fields)]
        pub struct $name {
            /// Where an editor finds the JSON Schema of the scene format, to complete and
            /// check fields as they are typed (`"../schema/scene.schema.json"` in the bundled
            /// scenes; `graphostatik schema` writes it). Not read by graphostatik.
            #[serde(default, rename = "$schema", skip_serializing_if = "Option::is_none")]
            pub schema: Option<String>,
            /// Which book procedure the scene is for (`graphostatik procedures` lists them);
            /// `"slider_crank"` when absent.
            #[serde(default)]
            pub procedure: Option<String>,
            /// Title written on the figure.
            pub title: String,
            /// Book reference written under the title, e.g. "LH Abb. 43, 49, 53, 65".
            #[serde(default)]
            pub source: Option<String>,
            /// Free notes on where the numbers come from (not drawn).
            #[serde(default)]
            pub notes: Option<String>,
            /// What the live preview (`graphostatik serve`) lets an author move: sliders over
            /// numeric fields of this scene. Not read by the construction.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub preview: Option<$crate::scene::Preview>,
            /// The numbers the book prints that this scene reproduces, each beside the check
            /// it stands for: `graphostatik check` shows them as book rows.
            #[serde(default, skip_serializing_if = "Vec::is_empty")]
            pub book: Vec<$crate::scene::BookValue>,
            /// What the book's plate letters, each written as a scene writes a name (`P1`
            /// for P₁, `II`, `s`, a shear field's `+`): the figure must write every one
            /// of them, which the figure test holds for the bundled scenes.
            #[serde(default, skip_serializing_if = "Vec::is_empty")]
            pub plate: Vec<String>,
            /// The paper `render` sets the figure on: `"a4"`, `"a3"`, `"a2"`, `"a1"` (an
            /// A-series sheet, the drawing reduced at a stated scale so that its lettering
            /// stays at least 2.5 mm high, on a larger sheet or split into pages where it
            /// does not fit) or `"fit"`, the figure's own size (the default).
            /// `render --paper` overrides it.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub paper: Option<$crate::protocol::Paper>,
            $($(#[$fm])* pub $field: $ty,)*
        }

        impl $crate::scene::procedure::SceneHeader for $name {
            fn procedure_field(&self) -> Option<&str> {
                self.procedure.as_deref()
            }
            fn title(&self) -> &str {
                &self.title
            }
            fn source(&self) -> &str {
                self.source.as_deref().unwrap_or("")
            }
            fn notes(&self) -> Option<&str> {
                self.notes.as_deref()
            }
            fn book(&self) -> &[$crate::scene::BookValue] {
                &self.book
            }
            fn preview(&self) -> Option<&$crate::scene::Preview> {
                self.preview.as_ref()
            }
            fn plate(&self) -> &[String] {
                &self.plate
            }
            fn paper(&self) -> Option<$crate::protocol::Paper> {
                self.paper
            }
        }
    };
}

pub(crate) use scene_struct;

/// Declares the outputs a procedure's scene can ask for, once: the enum a scene's `outputs`
/// field is read into (each variant by the name given), and the list of those names in the
/// order declared (`NAMES`, what `graphostatik procedures` prints).
macro_rules! output_enum {
    (
        $(#[$m:meta])*
        pub enum $name:ident {
            $($(#[$vm:meta])* $variant:ident = $text:literal),* $(,)?
        }
    ) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
        #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
        pub enum $name {
            $($(#[$vm])* #[serde(rename = $text)] $variant,)*
        }

        impl $name {
            /// Every output, by the name a scene gives it, in the order declared.
            pub const NAMES: &'static [&'static str] = &[$($text),*];
        }
    };
}

pub(crate) use output_enum;

/// What the live preview offers to move (`"preview": { "sliders": [ … ] }` in any scene).
///
/// ```json
/// "preview": { "sliders": [
///   { "field": "forces[1].angle_deg", "min": 200, "max": 340, "step": 1, "label": "direction of F2" }
/// ] }
/// ```
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Preview {
    /// One slider per numeric field to move; the construction replays at each position.
    #[serde(default)]
    pub sliders: Vec<Slider>,
}

/// A slider of the live preview over one number of the scene.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Slider {
    /// The number it moves, written as in error messages: `drawing.pole_kg[0]`,
    /// `forces[1].angle_deg`, `mechanism.crank_radius_mm`.
    pub field: String,
    /// Lowest value.
    pub min: f64,
    /// Highest value.
    pub max: f64,
    /// Step between values (default: a hundredth of the range).
    #[serde(default)]
    pub step: Option<f64>,
    /// What the slider is called on the page (default: the field).
    #[serde(default)]
    pub label: Option<String>,
}

impl Slider {
    /// The field as a JSON pointer (`forces[1].angle_deg` → `/forces/1/angle_deg`); `None`
    /// if it is not a path of names and indices.
    pub fn pointer(&self) -> Option<String> {
        let mut out = String::new();
        for part in self.field.split('.') {
            let (name, mut rest) = match part.find('[') {
                Some(i) => (&part[..i], &part[i..]),
                None => (part, ""),
            };
            if (name.is_empty() && out.is_empty())
                || !name
                    .bytes()
                    .all(|c| c.is_ascii_alphanumeric() || c == b'_' || c == b'$')
            {
                return None;
            }
            if !name.is_empty() {
                out.push('/');
                out.push_str(name);
            }
            while let Some(r) = rest.strip_prefix('[') {
                let (index, tail) = r.split_once(']')?;
                index.parse::<usize>().ok()?;
                out.push('/');
                out.push_str(index);
                rest = tail;
            }
            if !rest.is_empty() {
                return None;
            }
        }
        (!out.is_empty()).then_some(out)
    }

    /// The step, given or a hundredth of the range.
    pub fn step(&self) -> f64 {
        self.step.unwrap_or((self.max - self.min) / 100.0)
    }

    /// Why the slider cannot be used, if it cannot: a range that is not finite and
    /// increasing, a step that is not positive, a field that is not a path.
    pub fn problem(&self) -> Option<String> {
        if !(self.min.is_finite() && self.max.is_finite() && self.min < self.max) {
            return Some(format!("min {} must lie below max {}", self.min, self.max));
        }
        let step = self.step();
        if !(step.is_finite() && step > 0.0) {
            return Some(format!("step {step} must be positive"));
        }
        if self.pointer().is_none() {
            return Some(format!(
                "`{}` is not a field path such as forces[1].angle_deg",
                crate::fmt::clip(&self.field, 80)
            ));
        }
        None
    }
}
