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
        }
    };
}

pub(crate) use scene_struct;
