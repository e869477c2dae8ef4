// Stand-in for mbed's EthernetInterface.h: the sample apps include it, use nothing of it.
