// adhesiveWallInteraction for the clouds of type basicThermoCloud
#include "basicThermoCloud.H"
#include "AdhesiveWallInteraction.H"

makePatchInteractionModelType(AdhesiveWallInteraction, basicThermoCloud);
