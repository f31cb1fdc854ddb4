//! Rectangles of pixels: the part of an image a render, a farm tile or a file covers.

/// A rectangle of pixels: columns `x..x + width`, rows `y..y + height`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Region {
    /// Left column.
    pub x: u32,
    /// Top row.
    pub y: u32,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl Region {
    /// The whole of a `width` x `height` image.
    pub fn full(width: u32, height: u32) -> Region {
        Region { x: 0, y: 0, width, height }
    }

    /// Number of pixels.
    pub fn pixel_count(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// Band `index` (from 0) of `count` equal bands of rows of a `width` x `height` image:
    /// rows `index * height / count` up to `(index + 1) * height / count`, all columns. Bands
    /// differ in height by at most one row; every row is in exactly one band.
    pub fn band(width: u32, height: u32, index: u32, count: u32) -> Result<Region, String> {
        if count == 0 || count > height {
            return Err(format!("cannot cut {height} rows into {count} tiles: use 1 to {height} tiles"));
        }
        if index >= count {
            return Err(format!("tile {index} does not exist: tiles of {count} are numbered 0 to {}", count - 1));
        }
        let row = |i: u32| (u64::from(i) * u64::from(height) / u64::from(count)) as u32;
        let (top, bottom) = (row(index), row(index + 1));
        Ok(Region { x: 0, y: top, width, height: bottom - top })
    }

    /// True when `other` lies entirely inside this region.
    pub fn contains(&self, other: &Region) -> bool {
        let end = |a: u32, b: u32| u64::from(a) + u64::from(b);
        other.x >= self.x
            && other.y >= self.y
            && end(other.x, other.width) <= end(self.x, self.width)
            && end(other.y, other.height) <= end(self.y, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_cover_every_row_once() {
        for (h, n) in [(1, 1), (7, 3), (480, 7), (100, 100), (65_536, 9)] {
            let mut next = 0;
            for i in 0..n {
                let b = Region::band(5, h, i, n).unwrap();
                assert_eq!((b.x, b.width, b.y), (0, 5, next), "band {i} of {n} over {h} rows");
                assert!(b.height == h / n || b.height == h / n + 1);
                next = b.y + b.height;
            }
            assert_eq!(next, h);
        }
        assert!(Region::band(5, 4, 0, 5).unwrap_err().contains("1 to 4 tiles"));
        assert!(Region::band(5, 4, 0, 0).is_err());
        assert!(Region::band(5, 4, 4, 4).unwrap_err().contains("numbered 0 to 3"));
    }

    #[test]
    fn containment() {
        let r = Region { x: 2, y: 3, width: 4, height: 5 };
        assert!(r.contains(&r));
        assert!(r.contains(&Region { x: 5, y: 7, width: 1, height: 1 }));
        assert!(!r.contains(&Region { x: 5, y: 7, width: 2, height: 1 }));
        assert!(!r.contains(&Region { x: 1, y: 3, width: 1, height: 1 }));
        assert!(!r.contains(&Region { x: u32::MAX, y: 3, width: u32::MAX, height: 1 }));
    }
}
