//! The GPU backend: runs the emitted compute shader (`airlight_main`) through wgpu on
//! whatever adapter the machine has — Mesa's lavapipe (a CPU Vulkan driver) on machines
//! without a GPU.

use crate::layout::{RECORD_SIZE, RESULT_SIZE};
use std::borrow::Cow;

/// Which artifact to run.
#[derive(Clone, Copy, Debug)]
pub enum Shader<'a> {
    /// WGSL source (compiled by wgpu's naga).
    Wgsl(&'a str),
    /// SPIR-V words with the name of their compute entry point, handed to the driver as they
    /// are when the adapter supports pass-through, else translated by naga's SPIR-V front end.
    SpirV(&'a [u32], &'a str),
}

/// A device ready to run compute work.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    passthrough: bool,
    limits: wgpu::Limits,
}

impl Gpu {
    /// Opens the first adapter wgpu finds (`WGPU_BACKEND` etc. are honoured).
    pub fn new() -> Result<Gpu, String> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .map_err(|e| format!("no GPU adapter found ({e}); install a Vulkan driver, e.g. Debian's mesa-vulkan-drivers and libvulkan1"))?;
        let info = adapter.get_info();
        let passthrough = adapter.features().contains(wgpu::Features::PASSTHROUGH_SHADERS);
        let limits = adapter.limits();
        let required_features = if passthrough { wgpu::Features::PASSTHROUGH_SHADERS } else { wgpu::Features::empty() };
        let desc = wgpu::DeviceDescriptor {
            label: Some("airlight"),
            required_features,
            required_limits: limits.clone(),
            experimental_features: unsafe { wgpu::ExperimentalFeatures::enabled() },
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&desc)).map_err(|e| format!("cannot open the GPU device: {e}"))?;
        Ok(Gpu { device, queue, info, passthrough, limits })
    }

    /// Adapter name and backend, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan)`.
    pub fn describe(&self) -> String {
        format!("{} ({:?})", self.info.name, self.info.backend)
    }

    /// Whether SPIR-V reaches the driver as-is.
    pub fn spirv_passthrough(&self) -> bool {
        self.passthrough
    }

    fn module(&self, shader: Shader<'_>) -> wgpu::ShaderModule {
        match shader {
            Shader::Wgsl(src) => self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("airlight wgsl"),
                source: wgpu::ShaderSource::Wgsl(Cow::Borrowed(src)),
            }),
            Shader::SpirV(words, entry) if self.passthrough => unsafe {
                self.device.create_shader_module_passthrough(wgpu::ShaderModuleDescriptorPassthrough {
                    label: Some("airlight spirv"),
                    entry_points: Cow::Owned(vec![wgpu::PassthroughShaderEntryPoint {
                        name: Cow::Borrowed(entry),
                        workgroup_size: (crate::layout::WORKGROUP_SIZE, 1, 1),
                    }]),
                    spirv: Some(Cow::Borrowed(words)),
                    ..Default::default()
                })
            },
            Shader::SpirV(words, _) => self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("airlight spirv (naga)"),
                source: wgpu::ShaderSource::SpirV(Cow::Borrowed(words)),
            }),
        }
    }

    /// Runs `shader` over `records` (a whole number of records, `RECORD_SIZE` bytes each) and returns the
    /// 8-byte results, in batches that fit the adapter's limits. Progress on stderr when
    /// `progress` is set and there is more than one batch. Builds the pipeline on every call;
    /// [`Gpu::prepare`] once and [`Prepared::run`] many times to dispatch without that cost.
    pub fn run(&self, shader: Shader<'_>, records: &[u8], progress: bool) -> Result<Vec<u8>, String> {
        if records.len() % RECORD_SIZE != 0 {
            return Err("record buffer is not a whole number of records".into());
        }
        if records.is_empty() {
            return Ok(Vec::new());
        }
        self.prepare(shader).run(records, progress)
    }

    /// Compiles `shader` and builds its compute pipeline (entry `airlight_main` for WGSL, the
    /// named entry for SPIR-V; records at binding 0, results at binding 1, group 0) once, for
    /// any number of [`Prepared::run`] calls.
    pub fn prepare(&self, shader: Shader<'_>) -> Prepared<'_> {
        let module = self.module(shader);
        let entry = match shader {
            Shader::Wgsl(_) => "airlight_main",
            Shader::SpirV(_, entry) => entry,
        };
        // Explicit layout (pass-through shaders cannot have one derived): records read-only at
        // binding 0, results read-write at binding 1, group 0.
        let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let bgl = self.device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("airlight"),
            entries: &[storage(0, true), storage(1, false)],
        });
        let layout = self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("airlight"),
            bind_group_layouts: &[Some(&bgl)],
            immediate_size: 0,
        });
        let pipeline = self.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("airlight"),
            layout: Some(&layout),
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        Prepared { gpu: self, bgl, pipeline }
    }
}

/// A compiled compute pipeline on a [`Gpu`], from [`Gpu::prepare`].
pub struct Prepared<'g> {
    gpu: &'g Gpu,
    bgl: wgpu::BindGroupLayout,
    pipeline: wgpu::ComputePipeline,
}

impl Prepared<'_> {
    /// Runs the pipeline over `records` (a whole number of records, `RECORD_SIZE` bytes each) and returns the
    /// 8-byte results, exactly as [`Gpu::run`] does (which calls this): buffers are created,
    /// filled and read back per call, in batches that fit the adapter's limits.
    pub fn run(&self, records: &[u8], progress: bool) -> Result<Vec<u8>, String> {
        if records.len() % RECORD_SIZE != 0 {
            return Err("record buffer is not a whole number of records".into());
        }
        let n = records.len() / RECORD_SIZE;
        let mut out = Vec::with_capacity(n * RESULT_SIZE);
        if n == 0 {
            return Ok(out);
        }
        let gpu = self.gpu;
        let (bgl, pipeline) = (&self.bgl, &self.pipeline);
        let by_binding = gpu.limits.max_storage_buffer_binding_size as usize / RECORD_SIZE;
        let by_dispatch = gpu.limits.max_compute_workgroups_per_dimension as usize * crate::layout::WORKGROUP_SIZE as usize;
        let batch = by_binding.min(by_dispatch).min(1 << 18).max(crate::layout::WORKGROUP_SIZE as usize);
        let batches = n.div_ceil(batch);
        let start = std::time::Instant::now();
        for (b, chunk) in records.chunks(batch * RECORD_SIZE).enumerate() {
            let count = chunk.len() / RECORD_SIZE;
            let input = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("records"),
                size: chunk.len() as u64,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            gpu.queue.write_buffer(&input, 0, chunk);
            let size = (count * RESULT_SIZE) as u64;
            let output = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("results"),
                size,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("staging"),
                size,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("airlight"),
                layout: bgl,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: input.as_entire_binding() },
                    wgpu::BindGroupEntry { binding: 1, resource: output.as_entire_binding() },
                ],
            });
            let mut enc = gpu.device.create_command_encoder(&Default::default());
            {
                let mut pass = enc.begin_compute_pass(&Default::default());
                pass.set_pipeline(pipeline);
                pass.set_bind_group(0, &bind, &[]);
                pass.dispatch_workgroups(count.div_ceil(crate::layout::WORKGROUP_SIZE as usize) as u32, 1, 1);
            }
            enc.copy_buffer_to_buffer(&output, 0, &staging, 0, size);
            gpu.queue.submit([enc.finish()]);
            let slice = staging.slice(..);
            let (tx, rx) = std::sync::mpsc::channel();
            slice.map_async(wgpu::MapMode::Read, move |r| {
                let _ = tx.send(r);
            });
            gpu.device
                .poll(wgpu::PollType::Wait { submission_index: None, timeout: None })
                .map_err(|e| format!("GPU poll failed: {e}"))?;
            rx.recv().map_err(|e| e.to_string())?.map_err(|e| format!("cannot read results back: {e}"))?;
            {
                let view = slice.get_mapped_range().map_err(|e| format!("cannot read results back: {e:?}"))?;
                out.extend_from_slice(&view);
            }
            staging.unmap();
            if progress && batches > 1 && start.elapsed().as_secs_f64() > 1.0 {
                eprintln!("airlight: gpu batch {}/{} ({} records)", b + 1, batches, (b + 1) * batch.min(n));
            }
        }
        Ok(out)
    }
}

/// Two passes over point-light records (docs/DESIGN.md §4.1): `first` (the route entry,
/// [`crate::targets::route_compute_wgsl`]) over every record, then `rest` (the point entry,
/// [`crate::targets::point_compute_wgsl`]) over those `first` left with
/// [`STATUS_DEFERRED`](crate::layout::STATUS_DEFERRED), gathered into one buffer; their results
/// take the deferred ones' places. The same results as `rest` over every record, where a
/// driver that masks branches (or a GPU whose lanes share a branch) no longer charges every
/// ray for the closed forms a few need.
pub fn run_deferred(first: &Prepared<'_>, rest: &Prepared<'_>, records: &[u8], progress: bool) -> Result<Vec<u8>, String> {
    let mut out = first.run(records, progress)?;
    let deferred: Vec<usize> = out
        .chunks_exact(RESULT_SIZE)
        .enumerate()
        .filter(|(_, r)| crate::layout::unpack_result(r).1 == crate::layout::STATUS_DEFERRED)
        .map(|(i, _)| i)
        .collect();
    if deferred.is_empty() {
        return Ok(out);
    }
    let gathered: Vec<u8> = deferred.iter().flat_map(|&i| &records[i * RECORD_SIZE..(i + 1) * RECORD_SIZE]).copied().collect();
    let second = rest.run(&gathered, progress)?;
    for (&i, r) in deferred.iter().zip(second.chunks_exact(RESULT_SIZE)) {
        out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE].copy_from_slice(r);
    }
    Ok(out)
}
