// ML_MATERIAL_FEATURES: the ML_FEATURE_* bits (bindings.h) of what the scene's materials use,
// set by the renderer for every shader that reads a material or a G-buffer. 0 (none) unless set.
#ifndef ML_MATERIAL_FEATURES
#define ML_MATERIAL_FEATURES 0
#endif
#define ML_HAS(feature) ((ML_MATERIAL_FEATURES & (feature)) != 0)
// Do the material records hold every slot and the extensions' vec4s (bindings.h, ML_GPU_MATERIAL_VEC4S)?
#define ML_EXTENDED_MATERIAL_RECORD ((ML_MATERIAL_FEATURES & ML_FEATURES_EXTENDED_RECORD) != 0)
