//! Elements, quadrature and assembly: knows meshes and materials, never the language.
//!
//! The element library is called per element through [`element`]:
//! `stiffness`, `mass`, `stress`, `strain`, `gauss_points`; loads are in
//! [`loads`] (pressure), post-processing in [`stress`] (VMIS, Gauss points
//! to nodes). Conventions (dof order, AXIS per radian, output points) are
//! documented at the top of [`element`] and [`quadrature`].
pub mod absorbing;
pub mod ahmad;
pub mod bar;
pub mod beam;
pub mod beam_skin;
pub mod biot_savart;
pub mod colour;
pub mod combustion;
pub mod constitutive;
pub mod contact;
pub mod contact_weak;
pub mod coq2;
pub mod dst;
pub mod eccentric_bar;
pub mod element;
pub mod enclosed;
pub mod fibre_section;
pub mod finite_strain;
pub mod flow;
pub mod fofi;
pub mod fourier;
pub mod front;
pub mod gen_plane_strain;
pub mod geometric;
pub mod hooke_matrix;
pub mod impact;
pub mod incomp;
pub mod integrate;
pub mod joint;
pub mod kp;
pub mod level_set;
pub mod loads;
pub mod locate;
pub mod material;
pub mod pipe;
pub mod plate;
pub mod prestress;
pub mod principal;
pub mod quadrature;
pub mod shape;
pub mod shell;
pub mod shell_offset;
pub mod skin;
pub mod solid;
pub mod stress;
pub mod surface_force;
pub mod surface_vectors;
pub mod thermal;
pub mod thick_shell;
pub mod vec3;
pub mod work;
pub mod xfem;
pub mod xfem_c8r;
pub mod xfem_c8r_cut;

#[cfg(test)]
mod test_support;
#[cfg(test)]
mod tests_beam;
#[cfg(test)]
mod tests_coq2;
#[cfg(test)]
mod tests_integrate;
#[cfg(test)]
mod tests_patch;
#[cfg(test)]
mod tests_reduced;
#[cfg(test)]
mod tests_shell;
#[cfg(test)]
mod tests_solid;
#[cfg(test)]
mod tests_traction;
#[cfg(test)]
mod tests_xfem_c8r;

pub mod mesh;
pub mod meshing;
pub mod midside;
pub mod node_numbering;
pub mod tensor_frame;
