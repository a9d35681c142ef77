/**
 * @class   vtkEnvironmentMapSource
 * @brief   Procedural environment maps: constant, sun disk, two-tone sky.
 *
 * Test and demo environments with the output layout of vtkEnvironmentMapAlgorithm
 * (an equal-area octahedral map with its luminance quadtree). Every texel is the
 * mean radiance over its solid angle, computed exactly or by adaptive refinement,
 * so a sun much smaller than a texel keeps its power.
 *  - Constant: Color everywhere.
 *  - SunDisk: a disk of angular radius SunAngularRadius (degrees) around
 *    SunDirection with radiance SunRadiance, in front of a constant SkyColor (the
 *    sun replaces the sky inside the disk). The disk's power is
 *    2 pi (1 - cos r) * SunRadiance (~ pi r^2 SunRadiance for small r).
 *  - TwoToneSky: UpperColor for z > 0, LowerColor for z < 0 (+Z is up).
 * Intensity scales every radiance.
 */
#ifndef vtkEnvironmentMapSource_h
#define vtkEnvironmentMapSource_h

#include "vissweepFiltersModule.h"
#include "vtkEnvironmentMapAlgorithm.h"

class VISSWEEPFILTERS_EXPORT vtkEnvironmentMapSource : public vtkEnvironmentMapAlgorithm
{
public:
  static vtkEnvironmentMapSource* New();
  vtkTypeMacro(vtkEnvironmentMapSource, vtkEnvironmentMapAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum EnvironmentType
  {
    Constant = 0,
    SunDisk = 1,
    TwoToneSky = 2
  };

  ///@{
  /** The kind of environment. Default Constant. */
  vtkSetClampMacro(Type, int, Constant, TwoToneSky);
  vtkGetMacro(Type, int);
  void SetTypeToConstant() { this->SetType(Constant); }
  void SetTypeToSunDisk() { this->SetType(SunDisk); }
  void SetTypeToTwoToneSky() { this->SetType(TwoToneSky); }
  const char* GetTypeAsString();
  ///@}

  ///@{
  /** Edge of the octahedral map in texels, a power of two. Default 64. */
  vtkSetClampMacro(OctahedralSize, int, 1, 32768);
  vtkGetMacro(OctahedralSize, int);
  ///@}

  ///@{
  /** Constant: the radiance everywhere. Default (1, 1, 1). */
  vtkSetVector3Macro(Color, double);
  vtkGetVector3Macro(Color, double);
  ///@}

  ///@{
  /** SunDisk: direction towards the sun's centre (normalized here). Default (1, 0, 1). */
  vtkSetVector3Macro(SunDirection, double);
  vtkGetVector3Macro(SunDirection, double);
  ///@}

  ///@{
  /** SunDisk: angular radius in degrees, in [0, 180]. Default 0.27 (the Sun's). */
  vtkSetClampMacro(SunAngularRadius, double, 0.0, 180.0);
  vtkGetMacro(SunAngularRadius, double);
  ///@}

  ///@{
  /** SunDisk: radiance inside the disk. Default (1000, 1000, 1000). */
  vtkSetVector3Macro(SunRadiance, double);
  vtkGetVector3Macro(SunRadiance, double);
  ///@}

  ///@{
  /** SunDisk: radiance of the sky around the disk. Default (0, 0, 0). */
  vtkSetVector3Macro(SkyColor, double);
  vtkGetVector3Macro(SkyColor, double);
  ///@}

  ///@{
  /** TwoToneSky: radiance above (z > 0) and below (z < 0) the horizon. Defaults (1, 1, 1), (0, 0, 0). */
  vtkSetVector3Macro(UpperColor, double);
  vtkGetVector3Macro(UpperColor, double);
  vtkSetVector3Macro(LowerColor, double);
  vtkGetVector3Macro(LowerColor, double);
  ///@}

protected:
  vtkEnvironmentMapSource();
  ~vtkEnvironmentMapSource() override;

#if !defined(__VTK_WRAP__)
  int ComputeOutputSize() override;
  std::shared_ptr<vs::EnvironmentMap> ComputeMap() override;
  std::string DescribeSource() override;
#endif

  int Type = Constant;
  int OctahedralSize = 64;
  double Color[3] = { 1.0, 1.0, 1.0 };
  double SunDirection[3] = { 1.0, 0.0, 1.0 };
  double SunAngularRadius = 0.27;
  double SunRadiance[3] = { 1000.0, 1000.0, 1000.0 };
  double SkyColor[3] = { 0.0, 0.0, 0.0 };
  double UpperColor[3] = { 1.0, 1.0, 1.0 };
  double LowerColor[3] = { 0.0, 0.0, 0.0 };

private:
  vtkEnvironmentMapSource(const vtkEnvironmentMapSource&) = delete;
  void operator=(const vtkEnvironmentMapSource&) = delete;
};

#endif
