/**
 * @class   vtkSMVisSweepRepresentationProxy
 * @brief   The VisSweep Volume representation's proxy: its information comes from the server.
 *
 * ParaView pulls a proxy's information properties from one process, the client first
 * (vtkSMSessionClient::PullState), and a representation exists on the client too. In a
 * client-server session the client's copy never renders a volume (ParaView renders volumes where
 * the data is), so its AccumulatedSamples, Converged and LastError would read 0 and empty. This
 * proxy pulls them from the server's first process instead, which under MPI holds the counts of
 * all processes (vtkVisSweepVolumeRepresentation). In a builtin session nothing changes.
 */
#ifndef vtkSMVisSweepRepresentationProxy_h
#define vtkSMVisSweepRepresentationProxy_h

#include "vissweepParaViewRepresentationModule.h"
#include "vtkSMRepresentationProxy.h"

class VISSWEEPPARAVIEWREPRESENTATION_EXPORT vtkSMVisSweepRepresentationProxy : public vtkSMRepresentationProxy
{
public:
  static vtkSMVisSweepRepresentationProxy* New();
  vtkTypeMacro(vtkSMVisSweepRepresentationProxy, vtkSMRepresentationProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSMVisSweepRepresentationProxy();
  ~vtkSMVisSweepRepresentationProxy() override;

  void UpdatePropertyInformationInternal(vtkSMProperty* prop = nullptr) override;

private:
  vtkSMVisSweepRepresentationProxy(const vtkSMVisSweepRepresentationProxy&) = delete;
  void operator=(const vtkSMVisSweepRepresentationProxy&) = delete;
};

#endif
