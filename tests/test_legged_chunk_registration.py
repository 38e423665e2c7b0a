"""Registering a body's legged-chunk kernels (``bodies.legged_chunk.register``) and a link element
(``bodies.rigid_chain.register_link``) cannot break a kernel that is being typed, whatever the order of
imports and whatever the numba cache holds.

The failure this guards against (seen in a cold two-worker matrix: hybrid centipede cases ended with
"Cannot unify Function(<function poses>) and Function(<function poses>)" at ``fused/legged_walk.py``'s
``LC.poses(P)``): when each ``register`` added a numba overload of its own, numba's type of ``poses`` became
a new ``Function`` each time a body module registered.  A body module can be imported in the middle of
typing a kernel: a callee loaded from the numba cache has its cached signatures unpickled, which imports
the module of each pack class in them (the other worker had cached ``rigid_chain.advance_chain`` for the
mass-spring links, so typing the hybrid chunk imported ``massspring.myriapod``).  The next nested compile
refreshes numba's typing context, the kernel being typed meets a second type for ``poses``, and every
later attempt in that process fails the same way.

The sequence here is that one, with two tiny bodies written to a temporary directory, in subprocesses on a
fresh numba cache: process 1 caches a shared callee for body B's pack; process 2 imports only body A and
compiles a chunk kernel over A's pack (and a chain over A's link element) whose callee's cache index names
B's pack, so B's module registers while the chunk is being typed.  On the overload-per-body registration
the chunk failed with that TypingError (checked when this test was written; the same sequence with the real
bodies at 77cac4e -- process 1 one step of the mass-spring centipede's body, process 2 a fused FEM centipede then
a fused hybrid centipede on the same fresh cache -- failed the hybrid's chunk at ``legged_walk.py:106`` twice,
the second attempt at once, as in the matrix run); the test also checks that B
really was imported during the compile, so it cannot pass without exercising the sequence.  Cost: two
interpreters and a few small kernels: 5 s of CPU, 10 to 40 s of wall time on the loaded 2-core machine.
"""
import os
import subprocess
import sys
import textwrap
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

SHARED = """
from numba import njit

@njit(cache=True)
def inner(L):
    return L.a * 2.0
"""

BODY = """
from collections import namedtuple
import numpy as np
from bench_myriapoda.bodies.legged_chunk import register
from bench_myriapoda.bodies.rigid_chain import register_link
from shared_callee import inner

Pack{X} = namedtuple("Pack{X}", "a c R")

def _poses(P):
    return P.c, P.R

def _carry(P, kinematic, c_T, R_T):
    P.c[0, 0] += 1.0

def _sample(P, c_out, R_out, links_out):
    pass

def _step(P, world, dt):
    return 1, np.int64(inner(P) > 1e9)

def _link(L, A, B, M, W, C, acc, dt, step, flat, ground):
    return np.int64(inner(L) > 1e9), 0

register(Pack{X}, _poses, _carry, _sample, _step)
register_link(Pack{X}, _link)

def pack():
    return Pack{X}(1.5, np.zeros((2, 3)), np.zeros((2, 3, 3)))
"""

# the fused walk's use of the four functions (``fused.legged_walk.legged_chunk``) and the chain's use of its link
# element (``rigid_chain.advance_chain``), each around a pack type whose callee is compiled mid-typing
KERNELS = """
from numba import njit
from bench_myriapoda.bodies import legged_chunk as LC
from bench_myriapoda.bodies.rigid_chain import link_step

@njit(cache=True)
def chunk(P, n, kin, c_T, R_T, c_out, R_out, links_out):
    for k in range(n):
        c, R = LC.poses(P)
        LC.carry(P, kin, c_T, R_T)
        LC.sample(P, c_out, R_out, links_out)
        done, status = LC.step(P, 0, 0.0)
        if status != 0:
            return k + 1
    return n

@njit(cache=True)
def chain(L, n):
    for k in range(n):
        status, n_contact = link_step(L, 0, 0, 0, 0, 0, 0, 0.0, k, True, 0.0)
        if status != 0:
            return k + 1
    return n
"""

CACHE_B = """
import body_b, shared_callee
assert shared_callee.inner(body_b.pack()) == 3.0
"""

# two attempts each: after the failure every later attempt in the process failed too
COMPILE_A = """
import sys
import numpy as np
import body_a, kernels
assert "body_b" not in sys.modules
for attempt in range(2):
    got = kernels.chunk(body_a.pack(), 3, np.zeros(2, np.bool_), np.zeros((2, 3)), np.zeros((2, 3, 3)),
                        np.zeros((2, 3)), np.zeros((2, 3, 3)), np.zeros((1, 3)))
    assert got == 3, got
    assert kernels.chain(body_a.pack(), 4) == 4
assert "body_b" in sys.modules, "the sequence was not exercised: body B was not imported while compiling"
print("ok")
"""


def run(code: str, cwd: Path, env: dict) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


def test_a_body_registering_while_a_kernel_is_typed(tmp_path):
    mods = tmp_path / "mods"
    mods.mkdir()
    (mods / "shared_callee.py").write_text(textwrap.dedent(SHARED))
    (mods / "kernels.py").write_text(textwrap.dedent(KERNELS))
    for x in "ab":
        (mods / f"body_{x}.py").write_text(BODY.format(X=x.upper()))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba-cache"),
               PYTHONPATH=os.pathsep.join([str(REPO), str(mods)]))
    first = run(CACHE_B, mods, env)
    assert first.returncode == 0, first.stderr[-3000:]
    second = run(COMPILE_A, mods, env)
    assert second.returncode == 0 and "ok" in second.stdout, second.stderr[-3000:]
