//! The RGB8 canvas of the benchmark plots (the lighting validation's curves).

use std::path::Path;

use ocean_scene::image_file::{encode_png, write_atomically};

/// An RGB8 canvas.
pub struct Canvas {
    pub width: usize,
    pub height: usize,
    pixels: Vec<[u8; 3]>,
}

impl Canvas {
    pub fn new(width: usize, height: usize, background: [u8; 3]) -> Self {
        Self {
            width,
            height,
            pixels: vec![background; width * height],
        }
    }

    /// Sets a pixel; coordinates outside the canvas are ignored.
    pub fn set(&mut self, x: i64, y: i64, c: [u8; 3]) {
        if x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height {
            self.pixels[y as usize * self.width + x as usize] = c;
        }
    }

    /// A line from (x0, y0) to (x1, y1), one pixel wide (DDA).
    pub fn line(&mut self, x0: f64, y0: f64, x1: f64, y1: f64, c: [u8; 3]) {
        let steps = (x1 - x0).abs().max((y1 - y0).abs()).ceil().max(1.0) as usize;
        for i in 0..=steps {
            let t = i as f64 / steps as f64;
            let x = x0 + (x1 - x0) * t;
            let y = y0 + (y1 - y0) * t;
            self.set(x.round() as i64, y.round() as i64, c);
        }
    }

    /// An axis-aligned rectangle outline.
    pub fn rect(&mut self, x0: f64, y0: f64, x1: f64, y1: f64, c: [u8; 3]) {
        self.line(x0, y0, x1, y0, c);
        self.line(x1, y0, x1, y1, c);
        self.line(x1, y1, x0, y1, c);
        self.line(x0, y1, x0, y0, c);
    }

    /// Writes the canvas as a PNG file, atomically (`ocean_scene::image_file`).
    ///
    /// # Errors
    ///
    /// The encoder's or the file system's, naming `path`.
    pub fn write_png(&self, path: &Path) -> Result<(), String> {
        let raw: Vec<u8> = self.pixels.iter().flatten().copied().collect();
        let bytes = encode_png(
            self.width as u32,
            self.height as u32,
            png::ColorType::Rgb,
            png::BitDepth::Eight,
            &raw,
        )?;
        write_atomically(path, &bytes, || Ok(()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The canvas decodes to its own pixels, and only the PNG is left in the directory.
    #[test]
    fn a_canvas_round_trips() {
        let dir = std::env::temp_dir().join(format!("ocean-png-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mut c = Canvas::new(5, 3, [10, 20, 30]);
        c.set(4, 2, [200, 100, 0]);
        c.set(7, 1, [1, 1, 1]); // outside: ignored
        let path = dir.join("c.png");
        c.write_png(&path).unwrap();
        let mut reader =
            ::png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&path).unwrap()))
                .read_info()
                .unwrap();
        let mut buf = vec![0u8; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (5, 3));
        let mut want: Vec<u8> = [10u8, 20, 30].repeat(15);
        want[3 * 14..].copy_from_slice(&[200, 100, 0]);
        assert_eq!(&buf[..info.buffer_size()], &want[..]);
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
