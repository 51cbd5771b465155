// The library is built with hidden symbols; UVTK_API marks its interface.
#pragma once

#ifndef UVTK_API
#define UVTK_API __attribute__((visibility("default")))
#endif
