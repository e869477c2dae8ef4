"""The user's mros2 checkout the tests compile the real src/mros2.cpp from:
MROS2_ROOT, with no default (docs/testing.md says how a developer gets
one). Tests that need it carry the needs_mros2 marker; conftest.py skips
them, saying why, when it is not given."""

import os

MROS2_ROOT = os.environ.get('MROS2_ROOT', '')


def checkout_found(root=MROS2_ROOT):
    return bool(root) and os.path.isfile(os.path.join(root, 'src', 'mros2.cpp'))


def missing_reason(root=MROS2_ROOT):
    """Why the tests that need a checkout do not run."""
    if not root:
        return 'needs an mros2 checkout: set MROS2_ROOT (docs/testing.md)'
    return 'no mros2 checkout at MROS2_ROOT=%s (no src/mros2.cpp)' % root
