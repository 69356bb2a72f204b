// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The Foundation's releases have no heterogeneous reacting cloud (OpenCFD's
// basicHeterogeneousReactingCloud): nothing to register. The file is here
// because Make/files lists the same family files for both flavours.
