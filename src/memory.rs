//! The machine's memory: how much a render may take, and large buffers allocated without
//! aborting the process.
//!
//! Rust's `vec!` and `Vec::with_capacity` abort the whole process when the allocator
//! refuses; a size computed from a hostile file must never get that far. The render's
//! memory estimate (`prepare::estimate_memory`) is checked against [`available`] before
//! anything large is built, and the buffers whose size follows from a file or a density
//! are allocated with [`try_filled`] and [`try_reserve`], which turn a refused allocation
//! into an error naming what was too big.

use std::fmt;

/// Bytes of memory a new allocation can get without swapping: the kernel's estimate of
/// available memory, or what the process's control group leaves free when that is less.
/// `None` when the system does not say.
pub fn available() -> Option<u64> {
    let mut system = sysinfo::System::new().ok()?;
    system.refresh_memory();
    let machine = Some(system.available_memory()).filter(|&b| b > 0);
    let group = system.cgroup_limits().map(|c| c.free_memory);
    match (machine, group) {
        (Some(m), Some(g)) => Some(m.min(g)),
        (m, g) => m.or(g),
    }
}

/// A large allocation the allocator refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutOfMemory {
    /// What the memory was for, e.g. "the fur's points".
    pub what: String,
    /// Bytes asked for.
    pub bytes: u64,
}

impl fmt::Display for OutOfMemory {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "not enough memory for {} ({})", self.what, crate::stats::human_bytes(self.bytes))
    }
}

impl std::error::Error for OutOfMemory {}

fn refused<T>(what: &str, n: usize) -> OutOfMemory {
    OutOfMemory { what: what.into(), bytes: (n as u64).saturating_mul(std::mem::size_of::<T>() as u64) }
}

/// `n` copies of `value`, or an error naming `what` if the memory cannot be had.
pub fn try_filled<T: Clone>(value: T, n: usize, what: &str) -> Result<Vec<T>, OutOfMemory> {
    let mut v = Vec::new();
    try_reserve(&mut v, n, what)?;
    v.resize(n, value);
    Ok(v)
}

/// Reserves room for `additional` more items in `v` (growing it geometrically, as a push
/// does, so repeated calls stay linear), or an error naming `what`.
pub fn try_reserve<T>(v: &mut Vec<T>, additional: usize, what: &str) -> Result<(), OutOfMemory> {
    v.try_reserve(additional).map_err(|_| refused::<T>(what, v.len().saturating_add(additional)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_machine_reports_its_memory() {
        let bytes = available().expect("Linux reports available memory");
        assert!(bytes > 1 << 20, "{bytes}");
    }

    /// An impossible size is an error naming what it was for, not an abort.
    #[test]
    fn impossible_sizes_are_errors() {
        let e = try_filled([0.0f32; 4], usize::MAX / 8, "the fur's points").unwrap_err();
        assert_eq!(e.what, "the fur's points");
        assert!(e.to_string().starts_with("not enough memory for the fur's points ("), "{e}");
        let mut v = vec![1u8; 3];
        assert!(try_reserve(&mut v, usize::MAX - 8, "x").is_err());
        assert_eq!(v, [1, 1, 1], "a refused reservation keeps the contents");
        assert_eq!(try_filled(7u16, 5, "y").unwrap(), [7; 5]);
    }
}
