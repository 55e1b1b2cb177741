//! The air-light kernel as shaders, one module per step: [`targets`] fills the WGSL source
//! (`codegen/shaders/shader/`) with the kernel's numbers, validates it with naga and writes
//! every language naga emits (the committed `shaders-out/`); [`layout`] is the GPU record the
//! compute entry point reads; [`gpu`] runs a compute shader over records through wgpu;
//! [`agreement`] is the criterion by which a shader's result agrees with the CPU kernel.

pub mod agreement;
pub mod gpu;
pub mod layout;
pub mod targets;
pub mod unrolled;
