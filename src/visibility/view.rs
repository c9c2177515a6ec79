//! The camera of a figure: a view-projection matrix (column-major, as WebGL takes it) and a
//! viewport in pixels, y down; the page's own perspective camera ([`View::looking`]); the image of
//! a point, its clip coordinates, and the side of a plane the eye is on (the eye the homogeneous
//! point M⁻¹·(0, 0, 1, 0)).

use crate::error::{Error, Result};
use crate::tolerance::{CAMERA_UP_SINE, MAX_COORD};
use glam::{DMat4, DVec2, DVec3, DVec4};

/// A camera: the view-projection matrix and the viewport in pixels.
#[derive(Debug, Clone, Copy)]
pub struct View {
    matrix: DMat4,
    pub(super) width: f64,
    pub(super) height: f64,
    /// M⁻¹·(0, 0, 1, 0): the eye, homogeneous (w < 0 for a perspective camera, 0 for an
    /// orthographic one, whose xyz then points away from the viewer).
    eye: DVec4,
}

/// The image of a point: pixel coordinates (y down), its clip w, and the clip z + w (≥ 0 in
/// front of the near plane).
#[derive(Debug, Clone, Copy)]
pub(super) struct Image {
    pub(super) screen: DVec2,
    pub(super) w: f64,
}

impl View {
    /// A view from a column-major 4 × 4 view-projection matrix (16 numbers) and a viewport of
    /// `width` × `height` pixels. Refused: a matrix that is not finite or not invertible, a
    /// viewport that is not positive and finite.
    pub fn new(matrix: &[f64], width: f64, height: f64) -> Result<Self> {
        if matrix.len() != 16 {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: format!("needs 16 numbers (a column-major 4 × 4 matrix), got {}", matrix.len()).into(),
            });
        }
        if let Some((k, &x)) = matrix.iter().enumerate().find(|(_, x)| !x.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: format!("entry {k} is not finite ({x})").into(),
            });
        }
        for (name, x) in [("width", width), ("height", height)] {
            if !(x.is_finite() && x > 0.0 && x <= 1e6) {
                return Err(Error::InvalidParameter {
                    name: if name == "width" { "width" } else { "height" },
                    message: format!("{name} must be a number of pixels in (0, 1e6], got {x}").into(),
                });
            }
        }
        let m = DMat4::from_cols_slice(matrix);
        let det = m.determinant();
        if !(det.is_finite() && det != 0.0) {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: "the matrix is not invertible".to_string().into(),
            });
        }
        let eye = m.inverse() * DVec4::Z;
        if !eye.is_finite() {
            return Err(Error::InvalidParameter {
                name: "viewProj",
                message: "the matrix is not invertible".to_string().into(),
            });
        }
        Ok(View { matrix: m, width, height, eye })
    }

    /// The page's camera (`www/camera.js`): perspective with vertical field of view `fov_y`
    /// (radians) from `eye` towards `target`, z up (y up when looking along z), the near and far
    /// planes at 1/100 and 100 times the distance, on a `width` × `height` viewport. Refused: an
    /// eye or target with a coordinate beyond ±[`MAX_COORD`], an eye nearer the target than
    /// 1/[`MAX_COORD`], a field of view outside (0, π).
    pub fn looking(eye: DVec3, target: DVec3, fov_y: f64, width: f64, height: f64) -> Result<Self> {
        let distance = eye.distance(target);
        let within = |p: DVec3| p.abs().max_element() <= MAX_COORD;
        if !(within(eye) && within(target) && distance >= 1.0 / MAX_COORD) {
            return Err(Error::InvalidParameter {
                name: "eye",
                message: format!(
                    "need an eye and a target within ±{MAX_COORD:e}, at least {:e} apart, got {eye} and {target}",
                    1.0 / MAX_COORD
                )
                .into(),
            });
        }
        if !(fov_y > 0.0 && fov_y < std::f64::consts::PI) {
            return Err(Error::InvalidParameter {
                name: "fovY",
                message: format!("the field of view must be in (0, π), got {fov_y}").into(),
            });
        }
        let (near, far) = (distance / 100.0, distance * 100.0);
        let f = 1.0 / (fov_y / 2.0).tan();
        let aspect = width / height;
        let projection = DMat4::from_cols_array(&[
            f / aspect,
            0.0,
            0.0,
            0.0,
            0.0,
            f,
            0.0,
            0.0,
            0.0,
            0.0,
            (far + near) / (near - far),
            -1.0,
            0.0,
            0.0,
            2.0 * far * near / (near - far),
            0.0,
        ]);
        let z = (eye - target) / distance;
        let up = if z.cross(DVec3::Z).length() < CAMERA_UP_SINE { DVec3::Y } else { DVec3::Z };
        let x = up.cross(z).normalize();
        let y = z.cross(x);
        let look = DMat4::from_cols(
            DVec4::new(x.x, y.x, z.x, 0.0),
            DVec4::new(x.y, y.y, z.y, 0.0),
            DVec4::new(x.z, y.z, z.z, 0.0),
            DVec4::new(-x.dot(eye), -y.dot(eye), -z.dot(eye), 1.0),
        );
        View::new(&(projection * look).to_cols_array(), width, height)
    }

    pub(super) fn clip(&self, p: DVec3) -> DVec4 {
        self.matrix * p.extend(1.0)
    }

    pub(super) fn image_of_clip(&self, c: DVec4) -> Image {
        Image {
            screen: DVec2::new((c.x / c.w + 1.0) / 2.0 * self.width, (1.0 - c.y / c.w) / 2.0 * self.height),
            w: c.w,
        }
    }

    /// The pixel position of a point in front of the near plane (None behind it).
    pub fn project(&self, p: DVec3) -> Option<DVec2> {
        let c = self.clip(p);
        (c.z + c.w >= 0.0 && c.w > 0.0).then(|| self.image_of_clip(c).screen)
    }

    /// σ·(n·x − d) for the eye x: positive when the eye is on the side n points to.
    pub(super) fn eye_side(&self, n: DVec3, d: f64) -> f64 {
        -(n.dot(self.eye.truncate()) - self.eye.w * d)
    }
}

/// Points transformed by a 4 × 4 model matrix (column-major), or as they are.
pub fn transformed(points: &[DVec3], model: Option<&DMat4>) -> Vec<DVec3> {
    match model {
        None => points.to_vec(),
        Some(m) => points.iter().map(|&p| m.transform_point3(p)).collect(),
    }
}
#[cfg(test)]
mod tests {
    use super::super::fixtures::refused;
    use super::*;

    #[test]
    fn the_page_camera_puts_the_target_mid_screen_and_the_field_of_view_at_its_edges() {
        // from 10 before the target along +y, a field of view of 90° (tan 45° = 1) on 800 × 400
        // (aspect 2): z is up, x to the right; 10 above the target is the top edge, 20 to a side
        // a side edge
        let (eye, target) = (DVec3::new(3.0, -4.0, 2.0), DVec3::new(3.0, 6.0, 2.0));
        let v = View::looking(eye, target, std::f64::consts::FRAC_PI_2, 800.0, 400.0).unwrap();
        let at = |p: DVec3| v.project(p).unwrap();
        let close = |a: DVec2, b: [f64; 2]| (a - DVec2::from(b)).length() < 1e-9;
        assert!(close(at(target), [400.0, 200.0]), "{}", at(target));
        assert!(close(at(target + DVec3::new(0.0, 0.0, 10.0)), [400.0, 0.0]));
        assert!(close(at(target + DVec3::new(20.0, 0.0, -10.0)), [800.0, 400.0]));
        assert!(close(at(target - DVec3::new(20.0, 0.0, 0.0)), [0.0, 200.0]));
        // the near plane is a hundredth of the distance from the eye
        assert!(v.project(eye + DVec3::new(0.0, 0.1001, 0.0)).is_some());
        assert!(v.project(eye + DVec3::new(0.0, 0.0999, 0.0)).is_none());
        assert!(v.project(eye - DVec3::Y).is_none());
        // looking straight down, y is up on the screen
        let down =
            View::looking(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO, std::f64::consts::FRAC_PI_2, 400.0, 400.0).unwrap();
        assert!(close(down.project(DVec3::new(0.0, 10.0, 0.0)).unwrap(), [200.0, 0.0]));
        assert!(close(down.project(DVec3::new(10.0, 0.0, 0.0)).unwrap(), [400.0, 200.0]));
    }

    #[test]
    fn views_are_refused_by_name_at_their_bounds() {
        let (eye, t) = (DVec3::new(0.0, -5.0, 0.0), DVec3::ZERO);
        assert_eq!(refused(View::looking(t, t, 1.0, 100.0, 100.0)), "eye");
        for fov in [0.0, -0.5, std::f64::consts::PI, f64::NAN] {
            assert_eq!(refused(View::looking(eye, t, fov, 100.0, 100.0)), "fovY", "{fov}");
        }
        assert!(View::looking(eye, t, 3.1, 100.0, 100.0).is_ok());
        // eye and target within the coordinate limit, 2e150 apart: the target mid-screen
        // (2·far·near = 2·distance² would overflow from 9.5e153 on)
        let far = View::looking(DVec3::new(0.0, -1e150, 0.0), DVec3::new(0.0, 1e150, 0.0), 1.0, 100.0, 100.0).unwrap();
        crate::assert_near!(far.project(DVec3::new(0.0, 1e150, 0.0)).unwrap(), DVec2::new(50.0, 50.0), 1e-12);
        for beyond in [DVec3::new(0.0, -1.000_000_1e150, 0.0), DVec3::new(1e300, 0.0, 0.0), DVec3::NEG_INFINITY] {
            assert_eq!(refused(View::looking(beyond, t, 1.0, 100.0, 100.0)), "eye", "{beyond}");
            assert_eq!(refused(View::looking(DVec3::X, beyond, 1.0, 100.0, 100.0)), "eye", "{beyond}");
        }
        // as near as 1e−150, not nearer (2·far·near would no longer be a normal number)
        let near = View::looking(DVec3::new(0.0, -1e-150, 0.0), t, 1.0, 100.0, 100.0).unwrap();
        crate::assert_near!(near.project(DVec3::new(0.0, 1e-150, 0.0)).unwrap(), DVec2::new(50.0, 50.0), 1e-12);
        assert_eq!(refused(View::looking(DVec3::new(0.0, -0.999e-150, 0.0), t, 1.0, 100.0, 100.0)), "eye");
        let id: Vec<f64> = DMat4::IDENTITY.to_cols_array().to_vec();
        assert!(View::new(&id, 1e6, 1.0).is_ok());
        for (w, h, which) in
            [(0.0, 1.0, "width"), (1e6 + 1.0, 1.0, "width"), (1.0, -1.0, "height"), (1.0, f64::NAN, "height")]
        {
            assert_eq!(refused(View::new(&id, w, h)), which);
        }
        assert_eq!(refused(View::new(&id[..15], 1.0, 1.0)), "viewProj");
        let mut nan = id.clone();
        nan[5] = f64::INFINITY;
        assert_eq!(refused(View::new(&nan, 1.0, 1.0)), "viewProj");
        assert_eq!(refused(View::new(&[0.0; 16], 1.0, 1.0)), "viewProj");
    }

    /// The page camera: the near plane at a hundredth of the distance (0.1 here), to ±5·10⁻⁶ (the
    /// far plane's far − near in place of far + near would move it to 0.10001); "up" is z until
    /// the view direction is within the sine [`CAMERA_UP_SINE`] of z (exactly, here).
    #[test]
    fn the_page_camera_near_plane_and_up_direction() {
        let eye = DVec3::new(0.0, -10.0, 0.0);
        let v = View::looking(eye, DVec3::ZERO, 1.0, 400.0, 300.0).unwrap();
        assert!(v.project(eye + DVec3::new(0.0, 0.100_005, 0.0)).is_some());
        assert!(v.project(eye + DVec3::new(0.0, 0.099_995, 0.0)).is_none());
        let square = |eye: DVec3| View::looking(eye, DVec3::ZERO, std::f64::consts::FRAC_PI_2, 400.0, 400.0).unwrap();
        let tilted = square(DVec3::new(1e-9, 0.0, 1.0));
        assert_eq!(DVec3::new(1e-9, 0.0, 1.0).cross(DVec3::Z).length(), CAMERA_UP_SINE);
        // up is z: the view's right is the world's +y
        crate::assert_near!(tilted.project(DVec3::new(0.0, 0.5, 0.0)).unwrap(), DVec2::new(300.0, 200.0), 1e-6);
        // along z: up is y
        crate::assert_near!(
            square(DVec3::Z).project(DVec3::new(0.0, 0.5, 0.0)).unwrap(),
            DVec2::new(200.0, 100.0),
            1e-9
        );
    }

    #[test]
    fn transformed_moves_points_by_the_model_matrix() {
        let points = [DVec3::new(1.0, 2.0, 3.0), DVec3::new(-1.0, 0.0, 0.5)];
        assert_eq!(transformed(&points, None), points);
        let m = DMat4::from_translation(DVec3::new(10.0, 20.0, 30.0)) * DMat4::from_scale(DVec3::splat(2.0));
        assert_eq!(transformed(&points, Some(&m)), [DVec3::new(12.0, 24.0, 36.0), DVec3::new(8.0, 20.0, 31.0)]);
    }
}
