// SPDX-License-Identifier: MIT
//! Data parallelism behind the `parallel` feature: rayon's parallel iterators when it is on (the
//! default), else the same calls on the standard iterators, run in sequence. Both give the same
//! values in the same order (every parallel loop here writes its own slots or collects in
//! order; none reduces floating-point sums across threads).

#[cfg(feature = "parallel")]
pub(crate) use rayon::prelude::*;

#[cfg(not(feature = "parallel"))]
pub(crate) use sequential::*;

/// The sequential stand-ins, named as rayon names them.
#[cfg(not(feature = "parallel"))]
mod sequential {
    /// `into_par_iter` on anything iterable.
    pub(crate) trait IntoParallelIterator: IntoIterator + Sized {
        /// The iterator itself.
        fn into_par_iter(self) -> Self::IntoIter {
            self.into_iter()
        }
    }

    impl<I: IntoIterator> IntoParallelIterator for I {}

    /// `par_iter` and `par_chunks` on slices.
    pub(crate) trait ParallelSlice<T> {
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

    /// `par_chunks_mut` on slices.
    pub(crate) trait ParallelSliceMut<T> {
        /// [`slice::chunks_mut`].
        fn par_chunks_mut(&mut self, size: usize) -> std::slice::ChunksMut<'_, T>;
    }

    impl<T> ParallelSliceMut<T> for [T] {
        fn par_chunks_mut(&mut self, size: usize) -> std::slice::ChunksMut<'_, T> {
            self.chunks_mut(size)
        }
    }

    /// rayon's adaptors that the standard iterators lack.
    pub(crate) trait ParallelIterator: Iterator + Sized {
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
    }

    impl<I: Iterator> ParallelIterator for I {}
}
