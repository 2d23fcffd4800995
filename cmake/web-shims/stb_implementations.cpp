// The stb functions render uses, compiled for the web build (cmake/web.cmake): on the desktop
// they come compiled in Debian's libstb, here from the same headers of libstb-dev.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include "stb_image.h"
#include "stb_image_write.h"
#include "stb_truetype.h"
