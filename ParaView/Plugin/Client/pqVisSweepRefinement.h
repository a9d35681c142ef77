/**
 * pqVisSweepRefinement: refines VisSweep volumes in the GUI while the view is still.
 *
 * ParaView renders on demand; VisSweep's mapper adds SamplesPerFrame samples per pixel at each
 * still render. This auto-start component (loaded with the plugin in the GUI) re-renders the
 * active render view on a Qt timer while one of its visible "VisSweep Volume" representations
 * reports Converged 0 and no mouse button is down (a drag renders interactive frames: the
 * mapper's preview). It stops at convergence (MaximumSamples, or the TimeBudget spent) and on a
 * render error (the representation's LastError), so a failing render is not repeated forever. As
 * ParaView's pqViewStreamingBehavior does for OSPRay's progressive passes, but for VisSweep's
 * representations. In builtin sessions and with a pvserver (also under MPI): there the
 * representation's proxy (vtkSMVisSweepRepresentationProxy) reads the information properties from
 * the server, and each render is the server's (docs/paraview.md).
 */
#ifndef pqVisSweepRefinement_h
#define pqVisSweepRefinement_h

#include <QObject>
#include <QTimer>

class pqVisSweepRefinement : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqVisSweepRefinement(QObject* p = nullptr);
  ~pqVisSweepRefinement() override;

  void onStartup();
  void onShutdown();

private Q_SLOTS:
  void refine();

private:
  QTimer Timer;
  int LastReported = -1;
};

#endif
