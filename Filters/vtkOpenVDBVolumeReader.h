/**
 * @class   vtkOpenVDBVolumeReader
 * @brief   Reads a float grid of an OpenVDB (.vdb) file, or a sequence of files, into vtkImageData.
 *
 * Reads the grid named GridName (default "density") through the OpenVDB library into a
 * dense vtkImageData covering the grid's active voxel bounding box, grown by Padding voxels
 * on every side. Values are float point scalars named after the grid; voxels that are not
 * active (including the padding) hold the grid's background value.
 *
 * World space is kept: VDB voxel (i,j,k) holds the value at its centre, world position
 * xform.indexToWorld(i,j,k), and the output point for that voxel sits exactly there (VTK
 * point data = voxel centres). So the output's origin is indexToWorld of the bounding box's
 * lower corner, its spacing the voxel size, its extent starts at 0. Linear transforms without
 * rotation are supported (uniform or non-uniform scale plus translation; an axis with a
 * negative scale is flipped so the spacing stays positive); a rotation, shear or frustum
 * transform is an error ("non-axis-aligned transforms are not supported yet").
 *
 * Files. The first that is set of these is read:
 *  1. a list (AddFileName() ... ; RemoveAllFileNames() clears it),
 *  2. a printf pattern with one integer conversion, SetFilePattern("smoke_%04d.vdb"), over
 *     SetFileIndexRange(first, last) stepping by FileIndexIncrement (default 1),
 *  3. FileName (one file).
 *
 * Time. A list or pattern of more than one file is a time series in VTK's temporal
 * pipeline: RequestInformation publishes TIME_STEPS 0, 1, ..., n-1 (the position in the
 * sequence) and TIME_RANGE [0, n-1]; RequestData reads the step nearest to UPDATE_TIME_STEP
 * (clamped to the range) and sets DATA_TIME_STEP on the output. One file is not temporal.
 * (The time is the index, not the simulation time: the files hold no standard time; the
 * Mantaflow smoke keeps its frame number in the grid metadata "mantaflow_frame".)
 *
 * UnionBounds (default on). The active bounding box of a simulation grows or moves from frame
 * to frame. With UnionBounds on, every time step covers the union of all steps' active
 * bounding boxes (plus Padding), so the sequence has one fixed extent, origin and spacing
 * (what the renderer wants to update a volume in place). The union comes from the grid
 * metadata OpenVDB stores per grid (file_bbox_min/max), read without the voxels
 * (io::File::readGridMetadata), so RequestInformation opens every file but reads no voxel data
 * (a file without that metadata is read in full once to find its bounding box). All steps must
 * then share one transform; if they do not, a warning says so and each step covers its own box.
 * With UnionBounds off, each step covers only its own active box, and the whole extent the
 * reader publishes follows the step being requested (it changes in RequestUpdateExtent). That
 * suits consumers connected straight to the reader (a volume mapper, a writer, Python code
 * reading GetOutput()); an image filter in between keeps the extent of its last
 * RequestInformation and would crop other steps, so keep UnionBounds on in such pipelines.
 *
 * A grid with no active voxels (or a sequence whose steps have none, under UnionBounds) gives
 * a single voxel (plus Padding) of background at index (0,0,0), with a warning, not an error:
 * an empty frame is ordinary in a simulation and should render as nothing.
 *
 * Grid listing. After UpdateInformation(), GetNumberOfGrids() and GetGridName(i),
 * GetGridType(i), GetGridActiveVoxelCount(i), GetGridBounds(i, bounds) describe the grids of
 * the first file (from metadata only; note GetGridName() without an index is the grid to read).
 *
 * Errors are reported with vtkErrorMacro, name the file, and leave the output empty (never a
 * crash; OpenVDB's exceptions are caught): no file set, a missing or unreadable file, a file
 * that is not a VDB file or is truncated or corrupt, a grid name the file does not have (the
 * message lists the grids it has), a grid that is not a float grid, an unsupported transform,
 * grid statistics (file_bbox_min/max) that do not match the voxels, an output larger than
 * MaximumNumberOfPoints, a bad file pattern.
 *
 * Corrupt files. OpenVDB 10 trusts the sizes and counts it reads: a corrupt file can make it
 * allocate without bound or overflow a buffer (bloscFromStream copies a chunk before checking
 * its size). So before OpenVDB parses a file, the reader walks its structure and checks every
 * length, count and chunk size against the file (header, metadata, grid descriptors and grid
 * ends, transforms; and, before the voxels are read, the float tree's nodes and compressed
 * chunks, whose internal-node (tile) values it also decompresses: OpenVDB leaks the node it is
 * reading when a chunk fails to decompress mid-tree), reporting the file as truncated or
 * corrupt instead. Voxel values inside valid chunks are not checkable and are read as they are.
 * Files without grid offsets (written by openvdb::io::Stream) and files older than format 222
 * (OpenVDB 2.0) are refused: their trees cannot be checked.
 *
 * @code{.py}
 * import vissweep
 * r = vissweep.vtkOpenVDBVolumeReader()
 * r.SetFilePattern("Data/smoke/smoke_%04d.vdb")
 * r.SetFileIndexRange(4, 48)
 * r.SetFileIndexIncrement(4)
 * r.UpdateInformation()
 * print([r.GetGridName(i) for i in range(r.GetNumberOfGrids())])
 * r.UpdateTimeStep(3)      # the 4th file
 * print(r.GetOutput().GetDimensions(), r.GetOutput().GetSpacing())
 * @endcode
 */
#ifndef vtkOpenVDBVolumeReader_h
#define vtkOpenVDBVolumeReader_h

#include "vissweepFiltersModule.h"
#include "vtkImageAlgorithm.h"

class VISSWEEPFILTERS_EXPORT vtkOpenVDBVolumeReader : public vtkImageAlgorithm
{
public:
  static vtkOpenVDBVolumeReader* New();
  vtkTypeMacro(vtkOpenVDBVolumeReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** One .vdb file (used when no list and no pattern is set). */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** A list of files, one per time step, in order. Takes precedence over the pattern and FileName.
   */
  void AddFileName(VTK_FILEPATH const char* fileName);
  void RemoveAllFileNames();
  int GetNumberOfFileNames();
  const char* GetNthFileName(int i);
  ///@}

  ///@{
  /**
   * A printf pattern with exactly one integer conversion (%d, %i, %u, optionally with flags
   * and width, e.g. "smoke_%04d.vdb"; write %% for a literal %), expanded for the indices
   * FileIndexRange[0], FileIndexRange[0] + FileIndexIncrement, ... <= FileIndexRange[1].
   * Used when the list is empty. Default: none, range (0, 0), increment 1.
   */
  vtkSetStringMacro(FilePattern);
  vtkGetStringMacro(FilePattern);
  vtkSetVector2Macro(FileIndexRange, int);
  vtkGetVector2Macro(FileIndexRange, int);
  vtkSetClampMacro(FileIndexIncrement, int, 1, VTK_INT_MAX);
  vtkGetMacro(FileIndexIncrement, int);
  ///@}

  /** The files of the sequence as resolved by the last RequestInformation (0 before or on error).
   */
  int GetNumberOfTimeSteps();
  /** File of time step i of the last RequestInformation (nullptr when out of range). */
  const char* GetTimeStepFileName(int i);

  ///@{
  /** Name of the float grid to read. Default "density". */
  vtkSetStringMacro(GridName);
  vtkGetStringMacro(GridName);
  ///@}

  ///@{
  /** Background voxels added on every side of the active bounding box. Default 0. */
  vtkSetClampMacro(Padding, int, 0, 1 << 20);
  vtkGetMacro(Padding, int);
  ///@}

  ///@{
  /**
   * Every time step covers the union of all steps' active bounding boxes (one fixed extent
   * for the whole sequence), from the files' metadata. Default on. See the class description.
   */
  vtkSetMacro(UnionBounds, vtkTypeBool);
  vtkGetMacro(UnionBounds, vtkTypeBool);
  vtkBooleanMacro(UnionBounds, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Largest output (points) the reader will allocate; a bigger one is an error. A guard
   * against huge active tiles and corrupt metadata. Default 2^31 (8 GiB of floats).
   */
  vtkSetClampMacro(MaximumNumberOfPoints, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * The grids of the first file, after UpdateInformation() (also after a failure about the
   * grid, so a caller can show what the file holds). Out-of-range indices give nullptr / 0.
   * Type is the value type ("float", "double", "vec3s", "int32", "bool", ...). Bounds are the
   * world-space bounds (xmin, xmax, ymin, ymax, zmin, zmax) of the active voxels' centres,
   * i.e. of the output image with Padding 0; (1, -1, 1, -1, 1, -1) when the grid is empty.
   * Index bounds are the active bounding box in index space (imin, imax, jmin, ...).
   * They come from the statistics OpenVDB writes as grid metadata; for a grid without them
   * (rare: a writer must turn them off) the count is -1 and the bounds empty, except for the
   * grid to read, which is then read in full.
   */
  int GetNumberOfGrids();
  const char* GetGridName(int i);
  const char* GetGridType(int i);
  vtkIdType GetGridActiveVoxelCount(int i);
  void GetGridBounds(int i, double bounds[6]);
  void GetGridIndexBounds(int i, int bounds[6]);
  ///@}

  /** 1 when the file exists and starts with OpenVDB's magic number. */
  static int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkOpenVDBVolumeReader();
  ~vtkOpenVDBVolumeReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* FilePattern = nullptr;
  int FileIndexRange[2] = { 0, 0 };
  int FileIndexIncrement = 1;
  char* GridName = nullptr;
  int Padding = 0;
  vtkTypeBool UnionBounds = 1;
  vtkIdType MaximumNumberOfPoints = vtkIdType(1) << 31;

private:
  vtkOpenVDBVolumeReader(const vtkOpenVDBVolumeReader&) = delete;
  void operator=(const vtkOpenVDBVolumeReader&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
