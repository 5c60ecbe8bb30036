"""A spin barrier for two compiled threads sharing one collision (numba).

One collision at large ``N`` is split by the kernel into two halves of its angular orders, and
two threads advance them in lock step; they meet a few times per step (about 7) to add their
partial wall sums. A step at ``N = 1e4`` takes about 90 us, so the meeting must cost well under
a microsecond: a spinning barrier on two counters does (about 0.1-0.3 us on this project's
2-core machines), where a numba ``prange`` region per phase costs several microseconds.

numba has no atomics, and a plain load in a spin loop may be hoisted out of the loop by the
compiler; the two intrinsics below emit an acquire load and a release store (plain ``mov`` on
x86, with the compiler barrier that matters). A thread that spins for long yields its core
(``sched_yield``), so a shared, busy machine degrades to slow, never to stuck.
"""

from __future__ import annotations

from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic

__all__ = ["LINE", "barrier"]

LINE = 8
"""Stride, in int64 entries, between the two threads' counters (one 64-byte cache line)."""

# Spins before a waiting thread starts yielding its core on every further spin.
_SPINS_BEFORE_YIELD = 4096


@intrinsic
def _load_acquire(typingctx, arr, idx):
    """``arr[idx]`` as an atomic load with acquire ordering (int64 arrays)."""
    sig = types.int64(arr, idx)

    def codegen(context, builder, sig, args):
        aryty = sig.args[0]
        ary = context.make_array(aryty)(context, builder, args[0])
        ptr = cgutils.get_item_pointer(context, builder, aryty, ary, [args[1]])
        return builder.load_atomic(ptr, "acquire", 8)

    return sig, codegen


@intrinsic
def _store_release(typingctx, arr, idx, val):
    """``arr[idx] = val`` as an atomic store with release ordering (int64 arrays)."""
    sig = types.void(arr, idx, val)

    def codegen(context, builder, sig, args):
        aryty = sig.args[0]
        ary = context.make_array(aryty)(context, builder, args[0])
        ptr = cgutils.get_item_pointer(context, builder, aryty, ary, [args[1]])
        builder.store_atomic(args[2], ptr, "release", 8)
        return context.get_dummy_value()

    return sig, codegen


@intrinsic
def _sched_yield(typingctx):
    """POSIX ``sched_yield()``: give the core to another runnable thread."""
    sig = types.int32()

    def codegen(context, builder, sig, args):
        fnty = ir.FunctionType(ir.IntType(32), [])
        fn = cgutils.get_or_insert_function(builder.module, fnty, "sched_yield")
        return builder.call(fn, [])

    return sig, codegen


@njit(cache=True, nogil=True)
def barrier(flags, me, nthreads):
    """Meet the other thread; returns the number of this meeting (1, 2, ...).

    ``flags`` is an int64 array of ``2 * LINE`` zeros at the start, shared by the two threads
    (``me`` is 0 or 1). Everything a thread wrote before its call is visible to the other
    after the other's call returns. With ``nthreads == 1`` only the count advances, so that
    callers that index buffers by the meeting's parity behave the same in both modes.
    """
    n = flags[me * LINE] + 1
    if nthreads == 1:
        flags[me * LINE] = n
        return n
    _store_release(flags, me * LINE, n)
    other = (1 - me) * LINE
    spins = 0
    while _load_acquire(flags, other) < n:
        spins += 1
        if spins > _SPINS_BEFORE_YIELD:
            _sched_yield()
    return n
