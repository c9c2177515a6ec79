//! The Klein quadric: lines as points of P⁵ (beyond the paper; the background of its Section 4's
//! subdivision in line space and of every invariant of Sections 2 and 5).
//!
//! An oriented line with unit direction d through p has the normalised Plücker coordinates
//! (d, m), m = p × d. Up to a factor they are a point of the real projective 5-space P⁵, and the
//! points that are lines fill the quadric M: Ω(L, L) = 0 of the Klein form
//!
//!   Ω(L₁, L₂) = d₁·m₂ + d₂·m₁                                                          (K1)
//!
//! (Pottmann & Wallner, *Computational Line Geometry*, §2.1; the conventions page,
//! docs/src/conventions.md, "The Klein quadric"). Two lines meet or are parallel exactly when
//! Ω(L₁, L₂) = 0 (K2); a discrete ruled surface is a polygon on M, a regulus a conic (the
//! plane of P⁵ that three of its lines span cuts M in it), a linear complex a hyperplane
//! section.
//!
//! - [`point`]: a line as a point of P⁵, the Klein form and the Klein residual;
//! - [`image`]: the 3D image of P⁵ the reader steers, and the image of M in it;
//! - [`polygon`]: a ruled surface as a polygon on M, Ω of consecutive rulings (Ω = −h sin φ);
//! - [`net`]: a congruence's grid as a net on M, Ω on each edge;
//! - [`sections`]: a regulus's conic, a linear complex as a hyperplane section;
//! - [`departure`]: how far the line-space subdivision's points leave M before N brings them back.

pub mod departure;
pub mod image;
pub mod net;
pub mod point;
pub mod polygon;
pub mod sections;
