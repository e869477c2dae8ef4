/* Stand-in for lwIP's init.h: mROS v1 includes it, uses nothing of it. */
