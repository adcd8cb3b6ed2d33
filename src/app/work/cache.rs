//! Work made from the lab's parts (a sphere of triangles, heat maps, a measurement), kept
//! until what it was made from changes. The work is handed exactly what it is keyed on: the
//! parts it reads (keyed by their stamps) and the panel's own values (keyed by value), so
//! that what is read and what is keyed on are one list, as egui's `FrameCache` keys on its
//! input. Each cache counts what it made, for the frame log.

use std::any::Any;

use crate::app::lab::{Part, Stamp};

/// What work is made from, and its key.
pub trait Inputs {
    type Key: PartialEq + 'static;
    fn key(&self) -> Self::Key;
}

impl<T> Inputs for &Part<T> {
    type Key = Stamp;

    fn key(&self) -> Stamp {
        self.stamp()
    }
}

/// A value of the panel's own that the work reads (its settings, its size), keyed by value.
pub struct Own<T>(pub T);

impl<T: Clone + PartialEq + 'static> Inputs for Own<T> {
    type Key = T;

    fn key(&self) -> T {
        self.0.clone()
    }
}

macro_rules! tuple_inputs {
    ($($name:ident),+) => {
        impl<$($name: Inputs),+> Inputs for ($($name,)+) {
            type Key = ($($name::Key,)+);

            #[allow(non_snake_case)]
            fn key(&self) -> Self::Key {
                let ($($name,)+) = self;
                ($($name.key(),)+)
            }
        }
    };
}

tuple_inputs!(A);
tuple_inputs!(A, B);
tuple_inputs!(A, B, C);
tuple_inputs!(A, B, C, D);
tuple_inputs!(A, B, C, D, E);
tuple_inputs!(A, B, C, D, E, F);
tuple_inputs!(A, B, C, D, E, F, G);
tuple_inputs!(A, B, C, D, E, F, G, H);
tuple_inputs!(A, B, C, D, E, F, G, H, I);

/// A value made from inputs, and how many times it was made.
pub struct Cached<V> {
    name: &'static str,
    key: Option<Box<dyn Any>>,
    value: Option<V>,
    made: u64,
}

impl<V> Cached<V> {
    /// An empty cache, named for the frame log (`panel.what`).
    pub fn new(name: &'static str) -> Self {
        Self {
            name,
            key: None,
            value: None,
            made: 0,
        }
    }

    /// The value made from `inputs`: the kept one where the inputs are the same, else made
    /// again by `make` from them.
    pub fn get<I: Inputs>(&mut self, inputs: I, make: impl FnOnce(I) -> V) -> &V {
        let key = inputs.key();
        let same = self
            .key
            .as_ref()
            .and_then(|k| k.downcast_ref::<I::Key>())
            .is_some_and(|k| *k == key);
        match self.value.take() {
            Some(v) if same => self.value.insert(v),
            _ => {
                self.made += 1;
                self.key = Some(Box::new(key));
                self.value.insert(make(inputs))
            }
        }
    }

    /// The value last made, if any.
    pub fn last(&self) -> Option<&V> {
        self.value.as_ref()
    }

    /// The cache's name and how many values it has made.
    pub fn count(&self) -> (&'static str, u64) {
        (self.name, self.made)
    }
}
