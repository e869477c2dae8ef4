"""Where mROS apps run off the board: one subpackage per target.

A target builds the user's own mROS library and app, unchanged, for another
machine, standing in for the board's RTOS, network stack and drivers. It
uses the generator (through the make fragment) and knows nothing of catkin
or colcon.
"""
