//! The bytes of a load history's contact state ([`crate::Model::contact_state`]):
//! what a restart hands to [`crate::Model::set_contact_state`] to continue
//! bit for bit, in this model or another holding the same problem.

use crate::contact::discretisation::Discretisation;
use crate::error::{Error, Result};
use crate::solve::history::StepState;

/// The bytes of a contact state: a magic word, the fingerprint of B, the
/// fingerprint of the interface system the history began with, a checksum
/// of what follows, then the flags, the interface factor and the friction
/// state, little-endian.
const STATE_MAGIC: &[u8; 8] = b"TFEMCS02";
/// The first version's magic word: the same bytes without the interface
/// system's fingerprint. Still read, as a state whose factor is not
/// restored (its system is not known).
const STATE_MAGIC_1: &[u8; 8] = b"TFEMCS01";

pub(super) fn encode(state: &StepState, fingerprint: u64) -> Vec<u8> {
    let n = state.warm.len();
    let packed = &state.factor.packed;
    let mut out = Vec::with_capacity(8 + 40 + 2 * n + 8 * packed.len() + 9);
    out.extend_from_slice(STATE_MAGIC);
    out.extend_from_slice(&fingerprint.to_le_bytes());
    // 0: not known (read back as such).
    out.extend_from_slice(&state.base.unwrap_or(0).to_le_bytes());
    out.extend_from_slice(&[0; 8]);
    out.extend_from_slice(&(n as u64).to_le_bytes());
    out.extend_from_slice(&(packed.len() as u64).to_le_bytes());
    out.extend(state.warm.iter().map(|&a| u8::from(a)));
    out.extend(state.factor_active.iter().map(|&a| u8::from(a)));
    out.push(u8::from(state.factor.factored));
    out.extend_from_slice(&state.factor.min_eigenvalue.to_le_bytes());
    for v in packed {
        out.extend_from_slice(&v.to_le_bytes());
    }
    // Frictional states go on with their slip and loads; a frictionless
    // state keeps its bytes as they were.
    let f = &state.friction;
    if !f.anchors.is_empty() {
        out.extend_from_slice(&(f.anchors.len() as u64).to_le_bytes());
        for v in f.anchors.iter().chain(&f.loads) {
            out.extend_from_slice(&v.to_le_bytes());
        }
        // Where the path stands, for the sub-steps of the next step: the
        // load factor and every element's opening.
        if f.openings.len() == f.anchors.len() {
            out.extend_from_slice(&f.at.to_le_bytes());
            out.extend_from_slice(&f.load_key.to_le_bytes());
            for v in &f.openings {
                out.extend_from_slice(&v.to_le_bytes());
            }
        }
    }
    let sum = checksum(&out);
    out[24..32].copy_from_slice(&sum.to_le_bytes());
    out
}

/// A checksum of a version-2 state's bytes but its magic word and the
/// checksum itself (bytes 24..32): a state changed on its way back (a
/// flipped bit, a truncation that still parses) is refused rather than
/// restored. FNV-1a over 64-bit words, with the high bits folded back, so
/// that a 268 MB state (an interface of 8192 unknowns) sums in a fraction
/// of building it.
fn checksum(bytes: &[u8]) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    let mut eat = |w: u64| {
        h = (h ^ w).wrapping_mul(0x100_0000_01b3);
        h ^= h >> 29;
    };
    let rest = bytes.get(32..).unwrap_or_default();
    let words = bytes.get(8..24).unwrap_or_default().chunks_exact(8);
    let chunks = rest.chunks_exact(8);
    let tail = chunks.remainder();
    for w in words.chain(chunks) {
        eat(u64::from_le_bytes(w.try_into().expect("8 bytes")));
    }
    let mut last = [0u8; 8];
    last[..tail.len()].copy_from_slice(tail);
    eat(u64::from_le_bytes(last) ^ ((tail.len() as u64) << 56));
    h
}

/// The refusal of bytes that are not a contact state of this model, saying
/// why.
fn bad(why: &str) -> Error {
    Error::argument(format!("not a contact state of this model: {why}"))
}

/// The bytes of a contact state read in order, each read refused where
/// they are cut short.
struct Reader<'b> {
    bytes: &'b [u8],
    at: usize,
}

impl<'b> Reader<'b> {
    fn take(&mut self, n: usize) -> Result<&'b [u8]> {
        let end = self.at.checked_add(n).ok_or_else(|| bad("too long"))?;
        let slice = self
            .bytes
            .get(self.at..end)
            .ok_or_else(|| bad("it is cut short"))?;
        self.at = end;
        Ok(slice)
    }

    fn word(&mut self) -> Result<u64> {
        Ok(u64::from_le_bytes(
            self.take(8)?.try_into().expect("8 bytes"),
        ))
    }

    fn size(&mut self) -> Result<usize> {
        usize::try_from(self.word()?).map_err(|_| bad("size"))
    }

    fn flags(&mut self, n: usize) -> Result<Vec<bool>> {
        (self.take(n)?.iter())
            .map(|&v| match v {
                0 => Ok(false),
                1 => Ok(true),
                _ => Err(bad("a flag is neither 0 nor 1")),
            })
            .collect()
    }

    fn f64s(&mut self, n: usize) -> Result<Vec<f64>> {
        let bytes = self.take(n.checked_mul(8).ok_or_else(|| bad("size"))?)?;
        Ok(bytes
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
            .collect())
    }
}

/// What a contact state's header says: its index base (0: none) and its
/// checksum (both from version 2).
struct Header {
    base: Option<u64>,
    sum: Option<u64>,
}

/// The header of a contact state, refused when it has no magic word or
/// belongs to another contact mesh than the one of `fingerprint`.
fn header(r: &mut Reader<'_>, fingerprint: u64) -> Result<Header> {
    let version = match r.take(8)? {
        m if m == STATE_MAGIC => 2,
        m if m == STATE_MAGIC_1 => 1,
        _ => return Err(bad("no magic word")),
    };
    if r.word()? != fingerprint {
        return Err(bad("it belongs to another contact mesh"));
    }
    // The checksum is checked once the bytes have parsed, so that a
    // state cut short says so.
    let (base, sum) = match version {
        1 => (None, None),
        _ => (Some(r.word()?).filter(|&b| b != 0), Some(r.word()?)),
    };
    Ok(Header { base, sum })
}

/// The friction state after the factor, when the bytes go on
/// (frictional histories write it): each element's anchor, then its load,
/// then, where the bytes still go on, the load factor of the state, the
/// fingerprint of its loads and each element's opening (absent from an
/// older version's bytes: the load factor is then not known, NaN).
fn friction_tail(r: &mut Reader<'_>) -> Result<crate::contact::FrictionState> {
    let mut friction = crate::contact::FrictionState::default();
    if r.at < r.bytes.len() {
        let f = r.size()?;
        let mut values = r.f64s(f.checked_mul(2).ok_or_else(|| bad("size"))?)?;
        friction.loads = values.split_off(f);
        friction.anchors = values;
        // A NaN anchor is an open element's (docs/method.md §6.15).
        let anchors_ok = friction.anchors.iter().all(|x| x.is_finite() || x.is_nan());
        if !anchors_ok || !friction.loads.iter().all(|x| x.is_finite()) {
            return Err(bad("a friction value is not finite"));
        }
        friction.at = f64::NAN;
        if r.at < r.bytes.len() {
            friction.at = r.f64s(1)?[0];
            friction.load_key = r.word()?;
            friction.openings = r.f64s(f)?;
            if !friction.at.is_finite() || !friction.openings.iter().all(|x| x.is_finite()) {
                return Err(bad("a friction value is not finite"));
            }
        }
    }
    Ok(friction)
}

pub(super) fn decode(bytes: &[u8], fingerprint: u64) -> Result<StepState> {
    let r = &mut Reader { bytes, at: 0 };
    let Header { base, sum } = header(r, fingerprint)?;
    let (n, m) = (r.size()?, r.size()?);
    let warm = r.flags(n)?;
    let factor_active = r.flags(n)?;
    let factored = r.flags(1)?[0];
    let min_eigenvalue = f64::from_le_bytes(r.take(8)?.try_into().expect("8 bytes"));
    let packed = r.f64s(m)?;
    let friction = friction_tail(r)?;
    if r.at != bytes.len() {
        return Err(bad("bytes left over"));
    }
    if sum.is_some_and(|sum| sum != checksum(bytes)) {
        return Err(bad("its bytes were changed (checksum)"));
    }
    if !packed.iter().all(|v| v.is_finite()) || min_eigenvalue.is_nan() {
        return Err(bad("a factor value is not finite"));
    }
    Ok(StepState {
        warm,
        factor_active,
        factor: crate::solve::condensed::FactorSnapshot {
            packed,
            factored,
            min_eigenvalue,
        },
        friction,
        base,
    })
}

/// A fingerprint of the contact discretisation `d` (its elements of B and
/// their pairs, and the weighted gaps' nodes of its mortar pairs), which a
/// contact state names so that it is restored into its own. Of B alone
/// where no pair is under the mortar weighting: the states of earlier
/// versions are still read.
pub(super) fn fingerprint_of(d: &Discretisation) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    let mut eat = |v: u64| {
        for byte in v.to_le_bytes() {
            h = (h ^ byte as u64).wrapping_mul(0x100_0000_01b3);
        }
    };
    let b = d.elements();
    eat(b.len() as u64);
    for e in b {
        e.nodes.iter().for_each(|&n| eat(n as u64));
        eat(e.pair as u64);
    }
    for pair in d.gaps() {
        eat(pair.pair as u64);
        eat(pair.gaps.len() as u64);
        for g in &pair.gaps {
            eat(g.node as u64);
            g.coefficients.iter().for_each(|&(dof, _)| eat(dof as u64));
        }
    }
    h
}
