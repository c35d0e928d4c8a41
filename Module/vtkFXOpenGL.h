// vtkFXOpenGL.h: the OpenGL declarations of the VTK vtkFX builds against.
// VTK up to 9.3 loads OpenGL with GLEW (vtk_glew.h); 9.4 replaced it with
// glad (vtk_glad.h), which has no glewIsSupported: vtkFX asks for versions
// and extensions through vtkFXRenderUtilities::IsOpenGLSupported instead.
#ifndef vtkFXOpenGL_h
#define vtkFXOpenGL_h

#if defined(__has_include)
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif
#else
#include "vtk_glew.h"
#endif

#endif
// VTK-HeaderTest-Exclude: vtkFXOpenGL.h
