//! Elements, quadrature and assembly: knows meshes and materials, never the language.
pub mod bar;
pub mod beam;
pub mod element;
pub mod loads;
pub mod material;
pub mod mesh;
pub mod quadrature;
pub mod shape;
pub mod solid;
pub mod stress;

#[cfg(test)]
mod test_support;
#[cfg(test)]
mod tests_beam;
#[cfg(test)]
mod tests_patch;
#[cfg(test)]
mod tests_solid;
#[cfg(test)]
mod tests_traction;
