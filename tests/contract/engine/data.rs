//! Engine-side data: what an engine owns rather than reads from weft's
//! metadata (meshes, camera, light, environment), and the linear picture a
//! draw produces. Plain arrays, so that the harness can fill them from
//! anywhere.

/// A triangle mesh with the engine interface's vertex streams. Streams the
/// mesh lacks are fed as documented in [`Mesh::stream`].
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    /// xyz tangent, w bitangent sign.
    pub tangents: Vec<[f32; 4]>,
    pub uv0: Vec<[f32; 2]>,
    pub uv1: Vec<[f32; 2]>,
    pub colors: Vec<[f32; 4]>,
    /// Counter-clockwise front faces (the WGSL convention the metadata's
    /// `primitive.front_face` is stated in).
    pub indices: Vec<u32>,
}

impl Mesh {
    /// The per-vertex values of the engine-interface input `name`, as four
    /// f32s (the vertex format decides how many are uploaded). The contract
    /// does not say what to feed an input the mesh lacks; this engine uses
    /// uv1 = uv0 and colour = opaque white, and zero for anything else.
    pub fn stream(&self, name: &str) -> Result<Vec<[f32; 4]>, String> {
        let n = self.positions.len();
        let pick = |i: usize| -> [f32; 4] {
            match name {
                "position" => {
                    let p = self.positions[i];
                    [p[0], p[1], p[2], 1.0]
                }
                "normal" => {
                    let p = self.normals.get(i).copied().unwrap_or([0.0; 3]);
                    [p[0], p[1], p[2], 0.0]
                }
                "tangent" => self.tangents.get(i).copied().unwrap_or([0.0; 4]),
                "uv0" => {
                    let p = self.uv0.get(i).copied().unwrap_or([0.0; 2]);
                    [p[0], p[1], 0.0, 0.0]
                }
                "uv1" => {
                    let p = self
                        .uv1
                        .get(i)
                        .or_else(|| self.uv0.get(i))
                        .copied()
                        .unwrap_or([0.0; 2]);
                    [p[0], p[1], 0.0, 0.0]
                }
                _ => self.colors.get(i).copied().unwrap_or([1.0; 4]),
            }
        };
        match name {
            "position" | "normal" | "tangent" | "uv0" | "uv1" | "color" => {
                Ok((0..n).map(pick).collect())
            }
            other => Err(format!(
                "vertex input `{other}` is not one of the engine interface's"
            )),
        }
    }
}

/// Column-major 4×4 matrix (`m[column][row]`), the memory layout of WGSL's
/// `mat4x4<f32>`.
pub type Mat4 = [[f32; 4]; 4];

/// Camera and main light of one frame (group 0's `weft_frame`).
#[derive(Clone, Debug)]
pub struct FrameInputs {
    /// World → clip for WebGPU clip space (y up, z in [0, w]).
    pub view_proj: Mat4,
    /// World → view.
    pub view: Mat4,
    pub camera_position: [f32; 3],
    /// Towards the light (normalised by the engine before upload).
    pub light_direction: [f32; 3],
    /// Linear radiance.
    pub light_color: [f32; 3],
    pub exposure: f32,
    pub time: f32,
    /// Width and height of the colour target in pixels (`viewport`).
    pub viewport: [f32; 2],
}

/// The environment the engine provides: a GGX-prefiltered radiance cube
/// and its L2 SH irradiance (both in the engine interface's conventions).
#[derive(Clone, Debug)]
pub struct Environment {
    /// Face size of mip 0.
    pub size: u32,
    /// Per mip: 6 faces (+x, −x, +y, −y, +z, −z) of `size >> m` squared
    /// texels, face-major then row-major, linear RGBA.
    pub mips: Vec<Vec<[f32; 4]>>,
    /// `sh[i]` = RGB coefficient i (Y00, Y1−1, Y10, Y11, …), E(n)/π.
    pub sh: [[f32; 3]; 9],
}

impl Environment {
    /// A 1×1 black cube with zero SH: the environment of an engine without one.
    pub fn black() -> Environment {
        Environment {
            size: 1,
            mips: vec![vec![[0.0, 0.0, 0.0, 1.0]; 6]],
            sh: [[0.0; 3]; 9],
        }
    }
}

/// A linear HDR picture, row 0 at the top.
#[derive(Clone, Debug)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[f32; 4]>,
}

impl Image {
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        self.pixels[(y * self.width + x) as usize]
    }

    /// The picture upside down (rows in reverse order).
    pub fn flipped_rows(&self) -> Image {
        let w = self.width as usize;
        let pixels = self
            .pixels
            .chunks_exact(w)
            .rev()
            .flatten()
            .copied()
            .collect();
        Image {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// Pixels with a NaN or infinite channel.
    pub fn non_finite_count(&self) -> usize {
        self.pixels
            .iter()
            .filter(|p| p.iter().any(|c| !c.is_finite()))
            .count()
    }

    /// Reinhard (x / (1 + x) per channel) then sRGB8, alpha 255: the simple
    /// tone map both pictures of a comparison go through.
    pub fn to_srgb8(&self) -> Vec<u8> {
        let encode = |x: f32| -> u8 {
            let x = if x.is_finite() { x.max(0.0) } else { 0.0 };
            let t = f64::from(x / (1.0 + x));
            let s = weft_meta::bake::linear_to_srgb(t);
            (s * 255.0).round().clamp(0.0, 255.0) as u8
        };
        self.pixels
            .iter()
            .flat_map(|p| [encode(p[0]), encode(p[1]), encode(p[2]), 255])
            .collect()
    }
}

/// Rec. 709 luminance of a linear RGB value.
pub fn luminance(p: [f32; 4]) -> f32 {
    0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]
}
