"""ctest's entry to the pytest suite: exits 77 (ctest: skipped) when pytest or numpy is missing, so that a machine
without them reports the suite as skipped, never as passed. Usage: run_pytest.py TESTS_DIR [pytest arguments]."""
import sys

try:
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    print(f"python tests skipped: {e} (Debian: python3-pytest python3-numpy)", file=sys.stderr)
    sys.exit(77)

sys.exit(pytest.main(sys.argv[1:] + ["-p", "no:cacheprovider"]))
