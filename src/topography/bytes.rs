//! A bounds-checked cursor over a file's bytes: every read that would go
//! past the end is an error naming the offset, never a panic.

use super::Bad;

/// Reads little- or big-endian numbers and strings from a byte slice.
#[derive(Debug, Clone)]
pub(crate) struct Cursor<'a> {
    bytes: &'a [u8],
    pos: usize,
}

macro_rules! getters {
    ($($le:ident, $be:ident, $t:ty;)*) => {$(
        /// The next value, little-endian.
        pub(crate) fn $le(&mut self) -> Result<$t, Bad> {
            Ok(<$t>::from_le_bytes(self.array()?))
        }
        /// The next value, big-endian.
        #[allow(dead_code)]
        pub(crate) fn $be(&mut self) -> Result<$t, Bad> {
            Ok(<$t>::from_be_bytes(self.array()?))
        }
    )*};
}

impl<'a> Cursor<'a> {
    /// A cursor at offset 0.
    pub(crate) fn new(bytes: &'a [u8]) -> Self {
        Cursor { bytes, pos: 0 }
    }

    /// A cursor at `pos` (errors on reading when past the end).
    pub(crate) fn at(bytes: &'a [u8], pos: usize) -> Self {
        Cursor { bytes, pos }
    }

    /// The current offset.
    pub(crate) fn pos(&self) -> usize {
        self.pos
    }

    /// Bytes left after the current offset.
    pub(crate) fn remaining(&self) -> usize {
        self.bytes.len().saturating_sub(self.pos)
    }

    /// Moves to offset `pos`.
    pub(crate) fn seek(&mut self, pos: usize) {
        self.pos = pos;
    }

    /// The next `n` bytes.
    pub(crate) fn take(&mut self, n: usize) -> Result<&'a [u8], Bad> {
        let end = self.pos.checked_add(n).filter(|e| *e <= self.bytes.len());
        let Some(end) = end else {
            return Err(Bad::truncated(format!(
                "{n} bytes needed at offset {}, the file has {}",
                self.pos,
                self.bytes.len()
            )));
        };
        let out = &self.bytes[self.pos..end];
        self.pos = end;
        Ok(out)
    }

    /// Skips `n` bytes.
    pub(crate) fn skip(&mut self, n: usize) -> Result<(), Bad> {
        self.take(n).map(|_| ())
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], Bad> {
        let b = self.take(N)?;
        let mut out = [0u8; N];
        out.copy_from_slice(b);
        Ok(out)
    }

    /// The next byte.
    pub(crate) fn u8(&mut self) -> Result<u8, Bad> {
        Ok(self.array::<1>()?[0])
    }

    getters! {
        u16_le, u16_be, u16;
        i16_le, i16_be, i16;
        u32_le, u32_be, u32;
        i32_le, i32_be, i32;
        u64_le, u64_be, u64;
        i64_le, i64_be, i64;
        f32_le, f32_be, f32;
        f64_le, f64_be, f64;
    }

    /// A fixed-width text field (Latin-1), with NULs and surrounding
    /// spaces removed.
    pub(crate) fn fixed_str(&mut self, n: usize) -> Result<String, Bad> {
        Ok(latin1(self.take(n)?))
    }

    /// A NUL-terminated UTF-8 string (the NUL consumed).
    pub(crate) fn c_str(&mut self) -> Result<String, Bad> {
        let rest = &self.bytes[self.pos.min(self.bytes.len())..];
        let Some(end) = rest.iter().position(|b| *b == 0) else {
            return Err(Bad::truncated(format!(
                "a string at offset {} has no end",
                self.pos
            )));
        };
        let s = String::from_utf8_lossy(&rest[..end]).into_owned();
        self.pos += end + 1;
        Ok(s)
    }
}

/// Latin-1 bytes as text, with NULs and surrounding spaces trimmed.
pub(crate) fn latin1(b: &[u8]) -> String {
    let s: String = b.iter().map(|&c| c as char).collect();
    s.trim_matches('\0').trim().trim_matches('\0').to_string()
}

/// `n` values of `size` bytes decoded by `f` into `f64`s (the caller has
/// checked that `data` holds them).
pub(crate) fn decode<const N: usize>(data: &[u8], f: impl Fn([u8; N]) -> f64) -> Vec<f64> {
    data.chunks_exact(N)
        .map(|c| {
            let mut a = [0u8; N];
            a.copy_from_slice(c);
            f(a)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_in_both_orders_and_refuses_past_the_end() {
        let b = [1u8, 0, 0, 2, b'a', b'b', 0, b' '];
        let mut c = Cursor::new(&b);
        assert_eq!(c.u16_le().unwrap(), 1);
        assert_eq!(c.u16_be().unwrap(), 2);
        assert_eq!(c.c_str().unwrap(), "ab");
        assert_eq!(c.remaining(), 1);
        assert!(c.u16_le().unwrap_err().to_string().contains("offset 7"));
        assert_eq!(latin1(b"\xb5m\0\0  "), "\u{b5}m");
        let mut c = Cursor::at(&b, 100);
        assert!(c.u8().is_err());
        assert!(Cursor::new(&b).take(usize::MAX).is_err());
    }
}
