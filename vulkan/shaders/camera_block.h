// The camera block's layout, one list for both sides: the host writes it
// (src/methods/march/ray_setup.cpp) and the kernels read it
// (camera_rays.glsl); C++ and GLSL include this file. Double-float slots
// hold a value's hi at float 2 slot and its lo at 2 slot + 1; words are
// unsigned ints as float bits. Vectors take three slots, x y z.
#define VRI_CAMERA_FLOATS 128    /* the block; a pixel's extras follow it */
#define VRI_CAM_EYE 0            /* the eye, in the frame */
#define VRI_CAM_U 3              /* Camera::frame(): u, v, w */
#define VRI_CAM_V 6
#define VRI_CAM_W 9
#define VRI_CAM_ASPECT 12        /* width / height */
#define VRI_CAM_HALF_H 13        /* tan(fov_y / 2), or ortho_height / 2 in the frame */
#define VRI_CAM_BOX_LO 14        /* the box the rays are clipped to, in the frame */
#define VRI_CAM_BOX_HI 17
#define VRI_CAM_ORIGIN 20        /* the grid's origin (a mesh: its centre), in the frame */
#define VRI_CAM_INVERSE 23       /* grid units per frame unit */
#define VRI_CAM_STEP 26          /* the march's step, frame units */
#define VRI_CAM_SCALE 27         /* frame units per world unit (a power of two) */
#define VRI_CAM_WIDTH 56         /* words: the image's width, height, */
#define VRI_CAM_HEIGHT 57
#define VRI_CAM_FIRST 58         /* the chunk's first pixel, */
#define VRI_CAM_ORTHO 59         /* 1: orthographic, */
#define VRI_CAM_EXTRAS 60        /* floats a pixel after the block, */
#define VRI_CAM_PLANES 61        /* the clip planes that follow (0xffffffff: the clip keeps nothing), */
#define VRI_CAM_KERNEL_CUTS 62   /* 1: pixel_ray leaves the planes to the kernel (a mesh walk: clip_window) */
#define VRI_CAM_PLANE0 32        /* clip planes (n, d) of unit n, in the frame: 4 slots each, */
#define VRI_CAM_MAX_PLANES 8     /* up to 8 (slots 32 .. 63) */
