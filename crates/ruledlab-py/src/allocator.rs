//! The extension's memory: the system allocator (malloc, as CPython's and NumPy's), with large
//! blocks advised to use transparent huge pages, as NumPy advises its own arrays of 4 MiB and
//! more (`madvise(MADV_HUGEPAGE)`, NumPy's `alloc.c`). The arrays the core returns are its
//! vectors, handed to NumPy without a copy; on Linux, where transparent huge pages are given on
//! request ("madvise", the default of most distributions), a fresh 4 KiB page faults in on first
//! write, about a microsecond each: the 150 MB of the invariants of 10⁶ rulings would cost 37 000
//! faults, where NumPy's temporaries of the same size cost a hundred. With the advice the core's
//! results are paged in as NumPy's are (bench/python.py, the book's "Benchmarks of the core").
//! Elsewhere (no huge pages, not Linux) it is the system allocator unchanged.

use std::alloc::{GlobalAlloc, Layout, System};

/// Blocks of this size and more are advised to use huge pages (NumPy's threshold).
const LARGE: usize = 4 << 20;

/// The system allocator, large blocks advised to use transparent huge pages.
pub struct Allocator;

#[cfg(target_os = "linux")]
fn advise(block: *mut u8, size: usize) {
    if block.is_null() || size < LARGE {
        return;
    }
    // the whole pages inside the block (madvise wants a page-aligned start)
    let page = 4096;
    let start = (block as usize).next_multiple_of(page);
    let end = block as usize + size;
    if end > start {
        // SAFETY: [start, end) lies inside the block the system allocator just handed out, which
        // this process owns; MADV_HUGEPAGE changes how its pages are backed, never their contents,
        // and a refusal (no huge pages here) leaves the block as it was.
        #[allow(unsafe_code)]
        unsafe {
            libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise(_: *mut u8, _: usize) {}

// SAFETY: every call is the system allocator's, with the same arguments; `advise` only changes how
// a block's pages are backed.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Allocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract is System's
        let block = unsafe { System.alloc(layout) };
        advise(block, layout.size());
        block
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract is System's
        let block = unsafe { System.alloc_zeroed(layout) };
        advise(block, layout.size());
        block
    }

    unsafe fn dealloc(&self, block: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract is System's (the block came from it)
        unsafe { System.dealloc(block, layout) }
    }

    unsafe fn realloc(&self, block: *mut u8, layout: Layout, size: usize) -> *mut u8 {
        // SAFETY: the caller's contract is System's (the block came from it)
        let moved = unsafe { System.realloc(block, layout, size) };
        advise(moved, size);
        moved
    }
}
