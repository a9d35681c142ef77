#include "vtkSMVisSweepRepresentationProxy.h"

#include "vtkObjectFactory.h"
#include "vtkPVSession.h"
#include "vtkSMSession.h"

vtkStandardNewMacro(vtkSMVisSweepRepresentationProxy);

vtkSMVisSweepRepresentationProxy::vtkSMVisSweepRepresentationProxy() = default;

vtkSMVisSweepRepresentationProxy::~vtkSMVisSweepRepresentationProxy() = default;

void vtkSMVisSweepRepresentationProxy::UpdatePropertyInformationInternal(vtkSMProperty* prop)
{
  const vtkTypeUInt32 location = this->Location;
  const vtkTypeUInt32 servers = vtkPVSession::DATA_SERVER | vtkPVSession::DATA_SERVER_ROOT |
    vtkPVSession::RENDER_SERVER | vtkPVSession::RENDER_SERVER_ROOT;
  vtkSMSession* session = this->GetSession();
  // A client of a server (not the builtin session, where one process is all three): the server's.
  if ((location & vtkPVSession::CLIENT) && (location & servers) && session &&
    session->IsA("vtkSMSessionClient"))
  {
    this->Location = location & ~static_cast<vtkTypeUInt32>(vtkPVSession::CLIENT);
  }
  this->Superclass::UpdatePropertyInformationInternal(prop);
  this->Location = location;
}

void vtkSMVisSweepRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
