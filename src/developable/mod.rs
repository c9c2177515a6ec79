//! Developable strips and paper models (Section 3, beyond its approximate development).
//!
//! Section 3 bends a discrete ruled surface, pair of rulings by pair, into its conoidal model and
//! projects that onto a plane: "if we apply the procedure … to a developable surface, we get its
//! development". A discrete developable is a strip whose consecutive rulings are coplanar
//! (δ_{i,i+1} = 0 in (1)): each face between two rulings is a plane quadrilateral, and the strip
//! unfolds onto the plane face by face, every length and angle kept. This module makes such
//! strips and their flat patterns:
//!
//! - [`construct`]: the tangent surface, the cone, the cylinder and the rectifying developable of
//!   a directrix polygon, coplanar by construction;
//! - [`coplanar`]: when two consecutive rulings count as coplanar (torsal), and their δ;
//! - [`repair`]: a strip edited by hand made developable again, the edited rulings kept;
//! - [`unfold`]: the exact unfolding, checked to be an isometry;
//! - [`overlap`]: where a flat pattern overlaps itself, and its pieces that do not;
//! - [`approximate`]: for a skew ruled surface, Section 3's approximate development and the gaps it
//!   leaves;
//! - [`sheet`]: the pieces laid out for cutting, in millimetres, with glue tabs, a kerf offset, a
//!   check square and the pages of a tiled print.

pub mod approximate;
pub mod construct;
pub mod coplanar;
pub mod outline;
pub mod overlap;
pub mod repair;
pub mod sheet;
pub mod unfold;
