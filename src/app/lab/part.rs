//! One thing the panels share (the lights, the material, the rules…): its value and the stamp
//! of its last change. A part is read by anyone and written only through the lab's doors
//! (`Lab::edit`, `Lab::set`), which check every value that enters (`Checked`) and give the part
//! a new stamp; work made from parts keys on their stamps (`cache::Cached`).

use std::sync::atomic::{AtomicU64, Ordering};

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// When a part last changed: unique across every part of every lab in the process, so that
/// two stamps are equal only if they are the same change of the same part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Stamp(u64);

impl Stamp {
    fn next() -> Self {
        static CHANGES: AtomicU64 = AtomicU64::new(1);
        Self(CHANGES.fetch_add(1, Ordering::Relaxed))
    }
}

/// A shared value and its stamp.
#[derive(Clone, Debug)]
pub struct Part<T> {
    value: T,
    stamp: Stamp,
}

impl<T> Part<T> {
    pub fn new(value: T) -> Self {
        Self {
            value,
            stamp: Stamp::next(),
        }
    }

    pub fn stamp(&self) -> Stamp {
        self.stamp
    }

    /// Its value, the part given up.
    pub fn into_value(self) -> T {
        self.value
    }

    /// The value, writable: for the lab's doors only, which stamp it afterwards.
    pub(super) fn value_mut(&mut self) -> &mut T {
        &mut self.value
    }

    /// Marks a change: for the lab's doors only.
    pub(super) fn touch(&mut self) {
        self.stamp = Stamp::next();
    }
}

impl<T> std::ops::Deref for Part<T> {
    type Target = T;

    fn deref(&self) -> &T {
        &self.value
    }
}

impl<T: Default> Default for Part<T> {
    fn default() -> Self {
        Self::new(T::default())
    }
}

impl<T: PartialEq> PartialEq for Part<T> {
    /// The same value: when it was set does not matter to what it is.
    fn eq(&self, other: &Self) -> bool {
        self.value == other.value
    }
}

/// Saved and read as its value alone; read back, it is a new change. What it holds is
/// checked where it enters a lab (`Checked`), not here.
impl<T: Serialize> Serialize for Part<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.value.serialize(s)
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Part<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        T::deserialize(d).map(Self::new)
    }
}

/// A value that comes in from anyone (a widget, a link, a lesson, stored state, a file) and
/// must be brought within its range: a non-finite number is refused (the field keeps
/// `previous`'s value), an out-of-range one clamped. Each is said once, naming the field.
pub trait Checked {
    fn check(&mut self, previous: &Self) -> Vec<String>;
}

/// The checks' notes, named by the field they are about.
pub struct Notes(pub Vec<String>);

impl Notes {
    /// `x` finite (else `previous`, refused) and within `[lo, hi]` (else clamped).
    pub fn number(&mut self, field: &str, x: &mut f64, previous: f64, [lo, hi]: [f64; 2]) {
        if !x.is_finite() {
            self.0.push(format!(
                "{field}: {} refused, kept {}",
                crate::error::number(*x),
                short(previous)
            ));
            *x = previous;
        }
        let clamped = x.clamp(lo, hi);
        if clamped != *x {
            let side = if *x < lo { "below" } else { "above" };
            self.0.push(format!(
                "{field}: {} is {side} {}, set to {}",
                short(*x),
                short(if *x < lo { lo } else { hi }),
                short(clamped)
            ));
            *x = clamped;
        }
    }

    /// `x` as `number` says, as f32 (egui's widgets keep f32).
    pub fn number_f32(&mut self, field: &str, x: &mut f32, previous: f32, [lo, hi]: [f32; 2]) {
        let mut wide = f64::from(*x);
        let range = [f64::from(lo), f64::from(hi)];
        self.number(field, &mut wide, f64::from(previous), range);
        *x = wide as f32;
    }

    /// Each number of a fixed-size list, named `field[k]`.
    pub fn numbers<const N: usize>(
        &mut self,
        field: &str,
        xs: &mut [f64; N],
        previous: &[f64; N],
        range: [f64; 2],
    ) {
        for k in 0..N {
            self.number(&format!("{field}[{k}]"), &mut xs[k], previous[k], range);
        }
    }

    pub fn say(&mut self, note: String) {
        self.0.push(note);
    }
}

/// A number as a person reads it in a notice.
fn short(x: f64) -> String {
    crate::colormap::short_number(x)
}

/// Runs `f` over a fresh `Notes` and gives back what it said.
pub fn notes(f: impl FnOnce(&mut Notes)) -> Vec<String> {
    let mut n = Notes(Vec::new());
    f(&mut n);
    n.0
}
