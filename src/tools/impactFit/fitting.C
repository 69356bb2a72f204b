// The coefficient fits of src/fitting, compiled here so that their object
// stays in this application's Make/ folder
#include "ImpactFit.C"
