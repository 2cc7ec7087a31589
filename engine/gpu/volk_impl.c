/* volk's implementation, compiled once for the whole engine (Debian ships it as a header). */
#define VOLK_IMPLEMENTATION
#include <volk.h>
