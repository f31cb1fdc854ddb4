//! Hostile input: every parser gets random bytes, real files with random mutations, and
//! every truncation of its small real files. Whatever the bytes, the result is a clear
//! error or usable data: no panic, no hang, no unbounded allocation.
//!
//! The formats and their checks are in `tests/hostile/formats/`, shared with the cargo-fuzz
//! targets in `fuzz/` for longer campaigns. Set `PROPTEST_CASES` for a longer run here
//! (1000 cases per random test by default) and `HOSTILE_FORMAT` to one format's name (`ma`,
//! `usda`, ...: see [`formats::ALL`]) to give all of them to that format.

#[path = "hostile/formats/mod.rs"]
mod formats;

use formats::{Format, ALL};
use proptest::prelude::*;
use proptest::sample::Index;
use std::path::Path;

/// The seed files of a format, read from the repository.
fn seeds(format: &Format) -> Vec<Vec<u8>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    format.seeds.iter().map(|s| std::fs::read(root.join(s)).unwrap_or_else(|e| panic!("seed {s}: {e}"))).collect()
}

/// Values that often sit at the edge of a parser's cases, as bytes and as text.
const INTERESTING: &[&[u8]] = &[
    b"\0",
    b"\xff",
    b"\x7f\xff\xff\xff",
    b"\x00\x00\x80\x7f", // +inf as little-endian f32
    b"\x00\x00\xc0\x7f", // NaN
    b"\xff\xff\xff\xff",
    b"nan",
    b"inf",
    b"-1",
    b"0",
    b"1e39",
    b"4294967296",
    b"18446744073709551615",
    b"-9223372036854775808",
    b"\n",
    b" ",
    b"[",
    b"\"",
    b"{",
    b"#",
];

/// One edit of a file.
#[derive(Clone, Debug)]
enum Mutation {
    /// Flip one bit.
    Flip(Index, u8),
    /// Overwrite at a position with an interesting value.
    Overwrite(Index, Index),
    /// Insert an interesting value.
    Insert(Index, Index),
    /// Delete up to 16 bytes.
    Delete(Index, u8),
    /// Copy up to 64 bytes from one place over another (repeats structure).
    Splice(Index, Index, u8),
    /// Cut the file short.
    Truncate(Index),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<Index>(), 0u8..8).prop_map(|(i, b)| Mutation::Flip(i, b)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, v)| Mutation::Overwrite(i, v)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, v)| Mutation::Insert(i, v)),
        1 => (any::<Index>(), 1u8..16).prop_map(|(i, n)| Mutation::Delete(i, n)),
        1 => (any::<Index>(), any::<Index>(), 1u8..64).prop_map(|(a, b, n)| Mutation::Splice(a, b, n)),
        1 => any::<Index>().prop_map(Mutation::Truncate),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    let len = bytes.len();
    match *m {
        Mutation::Flip(i, bit) if len > 0 => bytes[i.index(len)] ^= 1 << bit,
        Mutation::Overwrite(i, v) if len > 0 => {
            let value = v.get(INTERESTING);
            let at = i.index(len);
            let end = (at + value.len()).min(len);
            bytes[at..end].copy_from_slice(&value[..end - at]);
        }
        Mutation::Insert(i, v) => {
            let at = i.index(len + 1);
            bytes.splice(at..at, v.get(INTERESTING).iter().copied());
        }
        Mutation::Delete(i, n) if len > 0 => {
            let at = i.index(len);
            bytes.drain(at..(at + n as usize).min(len));
        }
        Mutation::Splice(from, to, n) if len > 0 => {
            let (from, to) = (from.index(len), to.index(len));
            let n = (n as usize).min(len - from).min(len - to);
            bytes.copy_within(from..from + n, to);
        }
        Mutation::Truncate(i) => bytes.truncate(i.index(len + 1)),
        _ => {}
    }
}

/// Runs a format's check on bytes (whether they are accepted does not matter here).
fn check(format: &Format, bytes: &[u8]) {
    (format.check)(bytes);
}

/// Cases per random test: `PROPTEST_CASES` when set (as proptest reads it), else 1000, about
/// 100 per format and test, a few seconds in CI. `ProptestConfig::with_cases` alone would
/// override the variable.
fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .map(|v| v.parse().unwrap_or_else(|_| panic!("PROPTEST_CASES={v} is not a number of cases")));
    ProptestConfig::with_cases(cases.unwrap_or(1000))
}

/// The formats the random tests draw from: the one `HOSTILE_FORMAT` names, else all.
fn selected() -> Vec<&'static Format> {
    match std::env::var("HOSTILE_FORMAT") {
        Ok(name) => {
            let format = ALL.iter().find(|f| f.name == name);
            let names: Vec<_> = ALL.iter().map(|f| f.name).collect();
            vec![format.unwrap_or_else(|| panic!("HOSTILE_FORMAT={name} is none of {names:?}"))]
        }
        Err(_) => ALL.iter().collect(),
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn random_bytes_are_rejected_or_usable(
        format in proptest::sample::select(selected()),
        bytes in proptest::collection::vec(any::<u8>(), 0..600),
        prefix in any::<Index>(),
    ) {
        // Half of the cases start with the opening bytes of a real file, so they get past
        // signature checks into the parser proper.
        let mut bytes = bytes;
        if prefix.index(2) == 0 {
            let seed = &seeds(format)[0];
            bytes.splice(0..0, seed[..seed.len().min(64)].iter().copied());
        }
        check(format, &bytes);
    }

    #[test]
    fn mutated_real_files_are_rejected_or_usable(
        format in proptest::sample::select(selected()),
        seed in any::<Index>(),
        mutations in proptest::collection::vec(mutation(), 1..6),
    ) {
        let mut bytes = seed.get(&seeds(format)).clone();
        for m in &mutations {
            apply(&mut bytes, m);
        }
        check(format, &bytes);
    }
}

/// Every truncation (of files up to 16 KiB) and every single-bit flip (up to 1 KiB) of
/// each seed file: exhaustive, so the boundaries between fields are all covered, not only
/// those a random case lands on.
#[test]
fn every_truncation_and_bit_flip_of_small_real_files() {
    for format in ALL {
        for bytes in seeds(format) {
            if bytes.len() <= 16 << 10 {
                for cut in 0..bytes.len() {
                    check(format, &bytes[..cut]);
                }
            }
            if bytes.len() <= 1 << 10 {
                for i in 0..bytes.len() * 8 {
                    let mut flipped = bytes.clone();
                    flipped[i / 8] ^= 1 << (i % 8);
                    check(format, &flipped);
                }
            }
        }
    }
}

/// The seed files themselves are accepted, so the mutations start from valid input.
#[test]
fn seed_files_are_valid() {
    for format in ALL {
        for (bytes, name) in seeds(format).iter().zip(format.seeds) {
            assert!((format.check)(bytes), "{name} is rejected as {}", format.name);
        }
    }
}
