//! Zero heap allocations per evaluation: a counting global allocator wraps the
//! system one, and every evaluation entry point of the kernel — checked and unchecked,
//! f32 and f64, 4/6/12 terms, both expansions, lit sub-segments, the surface term and the
//! paper's algorithm — runs over property-generated scenes (every phase function and light
//! distribution, docs/DESIGN.md §3 extremes included) between two readings of the counter.
//!
//! The scenes are built *before* the first reading; only evaluation is counted, and only on the
//! thread that evaluates (the kernel starts none): on a loaded CI machine the process once
//! allocated while the test ran, presumably libtest's main thread, which waits for the test on a
//! channel (its waiting context is made on first use), so the allocator counts while a flag of
//! the calling thread is set, never elsewhere.

use airlight::glam::{DVec3, Vec3};
use airlight::{in_scatter_unchecked, Expansion};
use airlight_tests::scenes::{random, Aniso};
use airlight_tests::Rng;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting every allocation and reallocation made by a thread whose
/// [`COUNTING`] flag is set.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Whether this thread's allocations are counted (const-initialised, without a destructor:
    /// reading it never allocates).
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

fn count() {
    if COUNTING.try_with(Cell::get).unwrap_or(false) {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc_zeroed(layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn evaluation_never_allocates() {
    let mut rng = Rng(2026);
    let scenes: Vec<_> = (0..3000).map(|i| random(&mut rng, if i % 3 == 0 { Aniso::None } else { Aniso::Any }).rounded()).collect();
    let built: Vec<_> = scenes.iter().map(|p| (p.f64(), p.f32())).collect();
    let lit: Vec<_> = scenes
        .iter()
        .map(|p| {
            let end = if p.t_max.is_finite() { p.t_max } else { p.t_min + 50.0 };
            let third = (end - p.t_min) / 3.0;
            [(p.t_min, p.t_min + third), (p.t_min + 2.0 * third, p.t_max)]
        })
        .collect();
    COUNTING.set(true);
    // Sanity: the counter works (this Vec allocates).
    let before_probe = ALLOCATIONS.load(Ordering::SeqCst);
    let probe = vec![1u8; 16];
    assert!(ALLOCATIONS.load(Ordering::SeqCst) > before_probe, "the counting allocator does not count");
    drop(probe);

    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut checksum = 0.0f64;
    for ((s64, s32), segments) in built.iter().zip(&lit) {
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            checksum += s64.in_scatter_with::<4>(e) + s64.in_scatter_with::<6>(e) + s64.in_scatter_with::<12>(e);
            checksum += (s32.in_scatter_with::<4>(e) + s32.in_scatter_with::<6>(e)) as f64;
        }
        checksum += s64.in_scatter() + s32.in_scatter() as f64;
        checksum += s64.in_scatter_lit_with::<6>(segments, Expansion::Chebyshev) + s64.in_scatter_lit(segments);
        let seg32 = segments.map(|(a, b)| (a as f32, b as f32));
        checksum += s32.in_scatter_lit(&seg32) as f64;
        checksum += s32.in_scatter_lit_with::<4>(&seg32, Expansion::Chebyshev) as f64;
        checksum += s64.radiance(DVec3::Y, 0.3) + s32.radiance(Vec3::Y, 0.3) as f64;
        checksum += s64.in_scatter_paper::<6>(1e-12, 100) + s32.in_scatter_paper::<4>(1e-6, 100) as f64;
        checksum += in_scatter_unchecked::<f64, _, _, 6>(*s64.ray(), *s64.light(), *s64.medium(), *s64.phase(), Expansion::Chebyshev);
        checksum += in_scatter_unchecked::<f32, _, _, 4>(*s32.ray(), *s32.light(), *s32.medium(), *s32.phase(), Expansion::Chebyshev) as f64;
        checksum += airlight::atan_form(s64.ray(), s64.light().position, s64.light().intensity, s64.medium().sigma_s);
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    COUNTING.set(false);
    let evaluations = built.len() * 21; // the calls in the loop body above
    println!("{evaluations} evaluations, {} heap allocations (checksum {checksum:e})", after - before);
    assert_eq!(after - before, 0, "the kernel allocated {} times during {evaluations} evaluations", after - before);
    assert!(!checksum.is_nan());
}
