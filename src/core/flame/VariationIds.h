#pragma once
// The ids of flame/Variations.h by name, for Variations.cpp (tables, XformMap's constants) and
// VariationKernels.cpp (XformMap::apply): flam3 3.1.1's variation order, the parameter table's
// order, and the slots of XformMap::m_consts. Internal to src/core/flame.

namespace awb::flame::detail {

// flam3's variation index (its VAR_* constants).
enum Var : int {
    kLinear, kSinusoidal, kSpherical, kSwirl, kHorseshoe, kPolar, kHandkerchief, kHeart, kDisc,
    kSpiral, kHyperbolic, kDiamond, kEx, kJulia, kBent, kWaves, kFisheye, kPopcorn, kExponential,
    kPower, kCosine, kRings, kFan, kBlob, kPdj, kFan2, kRings2, kEyefish, kBubble, kCylinder,
    kPerspective, kNoise, kJulian, kJuliascope, kBlur, kGaussianBlur, kRadialBlur, kPie, kNgon,
    kCurl, kRectangles, kArch, kTangent, kSquare, kRays, kBlade, kSecant2, kTwintrian, kCross,
    kDisc2, kSuperShape, kFlower, kConic, kParabola, kBent2, kBipolar, kBoarders, kButterfly,
    kCell, kCpow, kCurve, kEdisc, kElliptic, kEscher, kFoci, kLazysusan, kLoonie, kPreBlur,
    kModulus, kOscilloscope, kPolar2, kPopcorn2, kScry, kSeparation, kSplit, kSplits, kStripes,
    kWedge, kWedgeJulia, kWedgeSph, kWhorl, kWaves2, kExp, kLog, kSin, kCos, kTan, kSec, kCsc,
    kCot, kSinh, kCosh, kTanh, kSech, kCsch, kCoth, kAuger, kFlux, kMobius,
    kVarCount
};

// The parameters, in the order flam3 writes them (variation by variation).
enum Param : int {
    kBlobLow, kBlobHigh, kBlobWaves,
    kPdjA, kPdjB, kPdjC, kPdjD,
    kFan2X, kFan2Y,
    kRings2Val,
    kPerspectiveAngle, kPerspectiveDist,
    kJulianPower, kJulianDist,
    kJuliascopePower, kJuliascopeDist,
    kRadialBlurAngle,
    kPieSlices, kPieRotation, kPieThickness,
    kNgonSides, kNgonPower, kNgonCircle, kNgonCorners,
    kCurlC1, kCurlC2,
    kRectanglesX, kRectanglesY,
    kDisc2Rot, kDisc2Twist,
    kSuperShapeRnd, kSuperShapeM, kSuperShapeN1, kSuperShapeN2, kSuperShapeN3, kSuperShapeHoles,
    kFlowerPetals, kFlowerHoles,
    kConicEccentricity, kConicHoles,
    kParabolaHeight, kParabolaWidth,
    kBent2X, kBent2Y,
    kBipolarShift,
    kCellSize,
    kCpowR, kCpowI, kCpowPower,
    kCurveXamp, kCurveYamp, kCurveXlength, kCurveYlength,
    kEscherBeta,
    kLazysusanSpin, kLazysusanSpace, kLazysusanTwist, kLazysusanX, kLazysusanY,
    kModulusX, kModulusY,
    kOscSeparation, kOscFrequency, kOscAmplitude, kOscDamping,
    kPopcorn2X, kPopcorn2Y, kPopcorn2C,
    kSeparationX, kSeparationXinside, kSeparationY, kSeparationYinside,
    kSplitXsize, kSplitYsize,
    kSplitsX, kSplitsY,
    kStripesSpace, kStripesWarp,
    kWedgeAngle, kWedgeHole, kWedgeCount, kWedgeSwirl,
    kWedgeJuliaAngle, kWedgeJuliaCount, kWedgeJuliaPower, kWedgeJuliaDist,
    kWedgeSphAngle, kWedgeSphCount, kWedgeSphHole, kWedgeSphSwirl,
    kWhorlInside, kWhorlOutside,
    kWaves2Freqx, kWaves2Scalex, kWaves2Freqy, kWaves2Scaley,
    kAugerSym, kAugerWeight, kAugerFreq, kAugerScale,
    kFluxSpread,
    kMobiusReA, kMobiusImA, kMobiusReB, kMobiusImB, kMobiusReC, kMobiusImC, kMobiusReD,
    kMobiusImD,
    kParamCount
};

// XformMap::m_consts: what flam3's xform_precalc keeps per xform, and the other per-xform
// constants its variation functions compute on every call.
enum Const : int {
    cPerspSin, cPerspDistCos,                    // sin a, dist cos a; a = angle pi/2
    cJulianAbsN, cJulianCn,                      // |power|, dist / power / 2
    cScopeAbsN, cScopeCn,
    cWedgeJuliaFactor, cWedgeJuliaAbsN, cWedgeJuliaCn,
    cJulianInvN, cScopeInvN, cWedgeJuliaInvN,    // 1 / power (the vector kernels' angle)
    cRadialSpin, cRadialZoom,                    // sin, cos of angle pi/2
    cWavesX, cWavesY,                            // 1 / (c^2 + eps), 1 / (f^2 + eps)
    cDisc2TimesPi, cDisc2SinAdd, cDisc2CosAdd,
    cSuperQuarterM, cSuperNegInvN1, cSuperRnd,
    cRingsDx,                                    // c^2 + eps
    cFanDx, cFanHalfDx,                          // pi (c^2 + eps), half of it
    cFan2Dx, cFan2HalfDx,
    cRings2Dx,
    cBlobSpan,                                   // high - low
    cNgonSector, cNgonHalfSector,                // 2 pi / sides, half of it
    cCpowAngleStep, cCpowRe, cCpowIm,            // 2 pi / power, r / power, i / power
    cCurveXlen2, cCurveYlen2,                    // lengths squared, at least 1e-20
    cEscherC, cEscherD,                          // (1 + cos beta) / 2, sin beta / 2
    cOscTwoPiF,
    cWedgeFactor, cWedgeSphFactor,               // 1 - angle count / (2 pi)
    cCellInvSize,
    cSeparationX2, cSeparationY2,
    cModulusX2, cModulusY2,                      // twice the half widths
    kConstCount
};

} // namespace awb::flame::detail
