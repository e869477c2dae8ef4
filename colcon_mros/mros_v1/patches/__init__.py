"""The opt-in patch set for the user's mROS v1 library: the fixes as
unified diffs (``*.patch``, each named for what it fixes, its first lines
saying so) and :mod:`.patch_set`, which applies, checks and reverts them."""
