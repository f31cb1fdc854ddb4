//! Process statistics for render summaries, and the memory of a prepared scene by part.

use crate::accel::{Accel, Shape};

/// Peak resident memory of this process in bytes (Linux `VmHWM`), if known. No well-kept
/// crate reports the peak (rather than the current) resident size portably; elsewhere this
/// is `None` and summaries leave the figure out.
pub fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Bytes as a short human-readable string (KiB, MiB, GiB).
pub fn human_bytes(bytes: u64) -> String {
    const UNITS: [&str; 4] = ["B", "KiB", "MiB", "GiB"];
    let mut v = bytes as f64;
    let mut unit = 0;
    while v >= 1024.0 && unit + 1 < UNITS.len() {
        v /= 1024.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} B")
    } else {
        format!("{v:.1} {}", UNITS[unit])
    }
}

/// CPU time consumed by this process so far (all threads); zero where the platform
/// cannot tell.
pub fn process_cpu_time() -> std::time::Duration {
    cpu_time::ProcessTime::try_now().map(|t| t.as_duration()).unwrap_or_default()
}

/// Counts and memory of a prepared scene by part, in bytes: what `tress info`, the render
/// summary and `tress bench` print.
#[derive(Clone, Copy, Debug, Default)]
pub struct Memory {
    /// Triangle meshes.
    pub meshes: u64,
    /// Their triangles.
    pub triangles: u64,
    /// Strand sets.
    pub strand_sets: u64,
    /// Their strands.
    pub strands: u64,
    /// Their hair segments.
    pub segments: u64,
    /// Strand points and offsets (and colours, when present, and the file's index of each
    /// strand when the set is stored in spatial order).
    pub strand_points: u64,
    /// Strand BVHs: nodes and segment ids.
    pub strand_bvh: u64,
    /// Mesh vertices, normals, UVs and indices.
    pub mesh: u64,
    /// Mesh BVHs.
    pub mesh_bvh: u64,
    /// The top-level BVH over the objects.
    pub top_bvh: u64,
}

impl Memory {
    /// Measures the objects of `accel`.
    pub fn of(accel: &Accel) -> Memory {
        let mut m = Memory::default();
        for o in &accel.objects {
            match &o.shape {
                Shape::Strands(s) => {
                    m.strand_sets += 1;
                    m.strands += s.strand_count() as u64;
                    m.segments += s.segment_count() as u64;
                    m.strand_points += s.memory_bytes() as u64;
                    m.strand_bvh += o.bvh_bytes() as u64;
                }
                Shape::Mesh(mesh) => {
                    m.meshes += 1;
                    m.triangles += mesh.indices.len() as u64;
                    m.mesh += mesh.memory_bytes() as u64;
                    m.mesh_bvh += o.bvh_bytes() as u64;
                }
            }
        }
        m.top_bvh = accel.bvh_bytes() as u64 - m.strand_bvh - m.mesh_bvh;
        m
    }

    /// Hair bytes per segment: points and BVH together.
    pub fn bytes_per_segment(&self) -> f64 {
        (self.strand_points + self.strand_bvh) as f64 / self.segments.max(1) as f64
    }
}
