// The exercise's umbrella header: what rope.h needs of CGL.
#ifndef CGL_CGL_H
#define CGL_CGL_H

#include "CGL/vector2D.h"

#endif  // CGL_CGL_H
