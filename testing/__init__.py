"""What the tests, the benchmarks and the main job (evaluation/) share, and
what is not installed: a ROS graph on this machine (rosmaster, ROS nodes,
an app of the PC target as a board) and a raw TCPROS peer. Each of them
imports this package from the repository; none imports the others."""
