"""Test configuration shared by all test files."""

import os

# One BLAS thread per process: the machines are small and shared, and threaded OpenBLAS turns
# the many small matrix products of the solvers into busy-waiting (measured 90x slower under
# load). Set before numpy is imported anywhere.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
os.environ.setdefault("MPLBACKEND", "Agg")


import pytest  # noqa: E402


@pytest.fixture(scope="module")
def client():
    """A real Dask cluster in this process (distributed is a core dependency)."""
    import distributed

    with (
        distributed.LocalCluster(
            n_workers=1, threads_per_worker=2, processes=False, dashboard_address=":0"
        ) as cluster,
        distributed.Client(cluster) as c,
    ):
        yield c


@pytest.fixture
def cli(capsys):
    """Run the command line in this process: ``cli(*args) -> (exit status, stdout, stderr)``."""
    from restitution.cli import _common, main

    def run(*args):
        _common._state["quiet"] = False
        try:
            main(list(args))
            code = 0
        except SystemExit as exc:
            code = exc.code
        out, err = capsys.readouterr()
        return code, out, err

    return run
