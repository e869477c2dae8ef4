"""Where the mROS v1 checkout the tests, the evaluation and the benchmark
build the real library from is: MROS_V1_ROOT, default ../shared/mros_v1
beside this repository. Tests that need it carry the needs_mros_v1 marker
(conftest.py skips them, saying why, when it is not there)."""

import os

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MROS_V1_ROOT = os.environ.get('MROS_V1_ROOT') or os.path.join(os.path.dirname(REPO), 'shared',
                                                              'mros_v1')


def checkout_found(root=MROS_V1_ROOT):
    return os.path.isfile(os.path.join(root, 'mros-lib', 'Makefile.m'))
