// SPDX-License-Identifier: MIT
//! Data parallelism behind the `parallel` feature, written once for the harmonic crates
//! (`hi-surface`, `hi-scan`, `hi-geomimage`, `hi-raytrace`): rayon's parallel iterators when it is on, else the
//! same calls on the standard iterators, run in sequence. Both give the same values in the same
//! order as long as each parallel loop writes its own slots or collects in order and reduces no
//! floating-point sum across threads, which is how the crates use it.
//!
//! A crate that uses it brings every name in with `use hi_par::*;` and forwards its own
//! `parallel` feature to `hi-par/parallel`.

#[cfg(feature = "parallel")]
pub use rayon::join;
#[cfg(feature = "parallel")]
pub use rayon::prelude::*;

#[cfg(not(feature = "parallel"))]
pub use sequential::*;

/// The sequential stand-ins, named as rayon names them.
#[cfg(not(feature = "parallel"))]
mod sequential {
    /// `into_par_iter` on anything iterable.
    pub trait IntoParallelIterator: IntoIterator + Sized {
        /// The iterator itself.
        fn into_par_iter(self) -> Self::IntoIter {
            self.into_iter()
        }
    }

    impl<I: IntoIterator> IntoParallelIterator for I {}

    /// Runs `a`, then `b`.
    pub fn join<A: FnOnce() -> RA, B: FnOnce() -> RB, RA, RB>(a: A, b: B) -> (RA, RB) {
        (a(), b())
    }

    /// `par_iter` and `par_chunks` on slices.
    pub trait ParallelSlice<T> {
        /// [`slice::iter`].
        fn par_iter(&self) -> std::slice::Iter<'_, T>;
        /// [`slice::chunks`].
        fn par_chunks(&self, size: usize) -> std::slice::Chunks<'_, T>;
    }

    impl<T> ParallelSlice<T> for [T] {
        fn par_iter(&self) -> std::slice::Iter<'_, T> {
            self.iter()
        }
        fn par_chunks(&self, size: usize) -> std::slice::Chunks<'_, T> {
            self.chunks(size)
        }
    }

    /// `par_iter_mut`, `par_chunks_mut` and `par_sort_unstable` on slices.
    pub trait ParallelSliceMut<T> {
        /// [`slice::iter_mut`].
        fn par_iter_mut(&mut self) -> std::slice::IterMut<'_, T>;
        /// [`slice::chunks_mut`].
        fn par_chunks_mut(&mut self, size: usize) -> std::slice::ChunksMut<'_, T>;
        /// [`slice::sort_unstable`].
        fn par_sort_unstable(&mut self)
        where
            T: Ord;
    }

    impl<T> ParallelSliceMut<T> for [T] {
        fn par_iter_mut(&mut self) -> std::slice::IterMut<'_, T> {
            self.iter_mut()
        }
        fn par_chunks_mut(&mut self, size: usize) -> std::slice::ChunksMut<'_, T> {
            self.chunks_mut(size)
        }
        fn par_sort_unstable(&mut self)
        where
            T: Ord,
        {
            self.sort_unstable();
        }
    }

    /// rayon's adaptors that the standard iterators lack.
    pub trait ParallelIterator: Iterator + Sized {
        /// The iterator itself: there are no splits to size.
        fn with_min_len(self, _min: usize) -> Self {
            self
        }

        /// `flat_map` over an ordinary iterator.
        fn flat_map_iter<U: IntoIterator, F: FnMut(Self::Item) -> U>(
            self,
            f: F,
        ) -> std::iter::FlatMap<Self, U, F> {
            self.flat_map(f)
        }

        /// `for_each` with one scratch value made by `init`.
        fn for_each_init<S, I: FnOnce() -> S, F: FnMut(&mut S, Self::Item)>(
            self,
            init: I,
            mut f: F,
        ) {
            let mut scratch = init();
            self.for_each(|item| f(&mut scratch, item));
        }

        /// `map` with one scratch value made by `init`.
        fn map_init<S, R, I: FnOnce() -> S, F: FnMut(&mut S, Self::Item) -> R>(
            self,
            init: I,
            mut f: F,
        ) -> impl Iterator<Item = R> {
            let mut scratch = init();
            self.map(move |item| f(&mut scratch, item))
        }
    }

    impl<I: Iterator> ParallelIterator for I {}
}

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
