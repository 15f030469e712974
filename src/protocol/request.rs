//! What a construction is asked to draw besides its core, written once: a procedure declares
//! its request as a set of named flags with [`request_set!`], and the same type is the
//! scene's `outputs` list (`"outputs": ["velocity", "acceleration"]`), its JSON Schema and the
//! construction's argument. There is no output enum to keep in step with a request struct.

/// Declares a request: a `Copy` struct of `bool` flags, one per output a scene may name,
/// read from and written as the list of the names set (the field names), with the list's
/// JSON Schema naming each output beside its doc comment.
///
/// ```
/// graphostatik::protocol::request_set! {
///     /// What to draw besides the positions.
///     pub struct Wants as "WantsOutput" {
///         /// The velocity diagram.
///         velocity,
///         /// The acceleration diagram.
///         acceleration,
///     }
/// }
/// let w: Wants = serde_json::from_str(r#"["acceleration"]"#).unwrap();
/// assert!(w.acceleration && !w.velocity);
/// assert_eq!(Wants::NAMES, &["velocity", "acceleration"]);
/// assert_eq!(serde_json::to_string(&w).unwrap(), r#"["acceleration"]"#);
/// let e = serde_json::from_str::<Wants>(r#"["speed"]"#).unwrap_err().to_string();
/// assert!(e.starts_with("unknown variant `speed`, expected `velocity` or `acceleration`"), "{e}");
/// ```
///
/// The second name (`"WantsOutput"`) is what the schema calls one item of the list.
#[macro_export]
macro_rules! request_set {
    (
        $(#[$m:meta])*
        pub struct $name:ident as $item:literal {
            $($(#[$fm:meta])* $field:ident),* $(,)?
        }
    ) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
        pub struct $name {
            $($(#[$fm])* pub $field: bool,)*
        }

        impl $name {
            /// Every output, by the name a scene gives it, in the order declared.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($field)),*];

            /// The flags in the order of [`Self::NAMES`].
            pub fn flags(&self) -> [bool; [$(stringify!($field)),*].len()] {
                [$(self.$field),*]
            }

            /// No output asked for.
            pub fn is_empty(&self) -> bool {
                !self.flags().contains(&true)
            }

            /// Sets the flag of the output at `index` in [`Self::NAMES`].
            fn set(&mut self, index: usize) {
                let flags = [$(&mut self.$field),*];
                if let Some(f) = flags.into_iter().nth(index) {
                    *f = true;
                }
            }
        }

        impl serde::Serialize for $name {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                use serde::ser::SerializeSeq;
                let on = self.flags();
                let mut seq = s.serialize_seq(Some(on.iter().filter(|f| **f).count()))?;
                for (name, f) in Self::NAMES.iter().zip(on) {
                    if f {
                        seq.serialize_element(name)?;
                    }
                }
                seq.end()
            }
        }

        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                d.deserialize_seq($crate::protocol::request::ListVisitor {
                    names: Self::NAMES,
                    out: Self::default(),
                    set: Self::set,
                })
            }
        }

        #[cfg(feature = "schema")]
        impl schemars::JsonSchema for $name {
            fn inline_schema() -> bool {
                true
            }
            fn schema_name() -> std::borrow::Cow<'static, str> {
                stringify!($name).into()
            }
            fn json_schema(g: &mut schemars::SchemaGenerator) -> schemars::Schema {
                $(#[$m])*
                #[derive(schemars::JsonSchema)]
                #[schemars(rename = $item)]
                #[allow(non_camel_case_types, dead_code)]
                enum Item {
                    $($(#[$fm])* $field,)*
                }
                <Vec<Item>>::json_schema(g)
            }
        }
    };
}

pub use crate::request_set;

/// Reads a list of output names into a request (the visitor [`request_set!`]'s types share).
#[doc(hidden)]
pub struct ListVisitor<T> {
    /// The names in declared order.
    pub names: &'static [&'static str],
    /// The request read so far.
    pub out: T,
    /// Sets the flag at an index of `names`.
    pub set: fn(&mut T, usize),
}

impl<'de, T> serde::de::Visitor<'de> for ListVisitor<T> {
    type Value = T;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a list of output names")
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(mut self, mut seq: A) -> Result<T, A::Error> {
        while let Some(i) = seq.next_element_seed(Name(self.names))? {
            (self.set)(&mut self.out, i);
        }
        Ok(self.out)
    }
}

/// One output name, read as its index among the names.
struct Name(&'static [&'static str]);

impl<'de> serde::de::DeserializeSeed<'de> for Name {
    type Value = usize;
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_str(self)
    }
}

impl serde::de::Visitor<'_> for Name {
    type Value = usize;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("an output's name")
    }

    fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<usize, E> {
        self.0
            .iter()
            .position(|n| *n == v)
            .ok_or_else(|| E::unknown_variant(v, self.0))
    }
}
