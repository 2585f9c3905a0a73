// The one compiled copy of stb_image (reading PNG and JPEG) and stb_image_write (writing PNG).
// They are single-header libraries: every file includes the declarations, and exactly one
// file defines the implementation. Compiling it here, rather than linking a platform's
// prebuilt library, makes the framework need only the headers on every platform
// (Debian's libstb-dev, vcpkg's stb, Homebrew) and gives each the same code.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
// The framework reads images from memory and writes them through a callback: no file is
// opened by stb, so paths (spaces, non-ASCII names on Windows) are the framework's alone.
#define STBI_NO_STDIO
#define STBI_WRITE_NO_STDIO
#include <stb_image.h>
#include <stb_image_write.h>
