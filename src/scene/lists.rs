//! Lists of exactly `N` numbers in scene files and stored state.

/// Exactly `N` numbers, as a list. serde's fixed-size arrays take the first `N` elements of a
/// longer TOML list and drop the rest without a word (a 4-element colour, a 5-element
/// position); and they are written as tuples, which RON (eframe's storage of the lab's state)
/// does not read back as a list.
pub mod exactly {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer, const N: usize>(v: &[f64; N], s: S) -> Result<S::Ok, S::Error> {
        v.as_slice().serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<[f64; N], D::Error> {
        let v = Vec::<f64>::deserialize(d)?;
        let len = v.len();
        v.try_into().map_err(|_| {
            serde::de::Error::invalid_length(
                len,
                &format!("a list of exactly {N} numbers").as_str(),
            )
        })
    }
}

/// `exactly` for an optional list, read (a light writes its vectors itself, `scene::Light`).
pub mod exactly_option {
    use serde::{Deserialize, Deserializer};

    pub fn deserialize<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<Option<[f64; N]>, D::Error> {
        // A list read as itself (not through a newtype, which RON writes differently).
        let Some(v) = Option::<Vec<f64>>::deserialize(d)? else {
            return Ok(None);
        };
        let len = v.len();
        v.try_into().map(Some).map_err(|_| {
            serde::de::Error::invalid_length(
                len,
                &format!("a list of exactly {N} numbers").as_str(),
            )
        })
    }
}
