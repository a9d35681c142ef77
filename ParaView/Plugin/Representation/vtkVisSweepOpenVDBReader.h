/**
 * @class   vtkVisSweepOpenVDBReader
 * @brief   ParaView's reader of OpenVDB (.vdb) files: VisSweep's vtkOpenVDBVolumeReader.
 *
 * ParaView makes proxies of classes its client-server wrapping knows, and VisSweep's libraries are
 * not wrapped for it; this class, wrapped with the plugin, holds a vtkOpenVDBVolumeReader, forwards
 * the settings a ParaView user sets (the files, the grid, the padding, the union of the steps'
 * bounds) and passes its output on: one float grid as image data in world space, a list of files
 * as time steps (vtkOpenVDBVolumeReader's documentation says how). The reader's errors (a missing
 * or corrupt file, a grid the file does not have, with the grids it has) reach ParaView's output
 * window and leave the output empty.
 *
 * Under MPI every process reads the file and keeps the piece ParaView asks it for.
 */
#ifndef vtkVisSweepOpenVDBReader_h
#define vtkVisSweepOpenVDBReader_h

#include "vissweepParaViewRepresentationModule.h"
#include "vtkImageAlgorithm.h"

class vtkOpenVDBVolumeReader;

class VISSWEEPPARAVIEWREPRESENTATION_EXPORT vtkVisSweepOpenVDBReader : public vtkImageAlgorithm
{
public:
  static vtkVisSweepOpenVDBReader* New();
  vtkTypeMacro(vtkVisSweepOpenVDBReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The files, one per time step (ParaView's FileNames property). */
  void AddFileName(const char* fileName);
  void RemoveAllFileNames();
  ///@}

  ///@{
  /** Forwarded to vtkOpenVDBVolumeReader. */
  void SetGridName(const char* name);
  const char* GetGridName();
  void SetPadding(int padding);
  void SetUnionBounds(int on);
  ///@}

  /** Whether the file looks like an OpenVDB file (ParaView's reader factory asks). */
  static int CanReadFile(const char* fileName);

  /** Includes the reader's. */
  vtkMTimeType GetMTime() override;

protected:
  vtkVisSweepOpenVDBReader();
  ~vtkVisSweepOpenVDBReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkVisSweepOpenVDBReader(const vtkVisSweepOpenVDBReader&) = delete;
  void operator=(const vtkVisSweepOpenVDBReader&) = delete;

  vtkOpenVDBVolumeReader* Reader;
};

#endif
