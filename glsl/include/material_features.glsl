// ML_MATERIAL_FEATURES: the ML_FEATURE_* bits (bindings.h) of what the scene's materials use,
// set by the renderer for every shader that reads a material or a G-buffer. 0 (none) unless set.
#ifndef ML_MATERIAL_FEATURES
#define ML_MATERIAL_FEATURES 0
#endif
#define ML_HAS(feature) ((ML_MATERIAL_FEATURES & (feature)) != 0)
