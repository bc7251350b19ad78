// stb's image reader and writer, which the native build takes from Debian's libstb (a host library):
// the browser build compiles them here.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
