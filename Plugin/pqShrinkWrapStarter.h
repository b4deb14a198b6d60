/**
 * @class   pqShrinkWrapStarter
 * @brief   What the ParaView client does for a Shrink Wrap created from its menus.
 *
 * After the first Apply the view shows the finished wrap: the animation goes to the wrap's last
 * step (Play then shows the evolution from its start), the wrap is coloured by Distance over the
 * shown wrap's range with its legend, and the target beside it is drawn grey (a mesh by its edges);
 * the target as measured (output port 1, hidden until the user shows it) gets its colours ready,
 * DistanceToWrap on a diverging map centred at 0. Created with a mesh and its distance field
 * selected (both go to Input), the panel's Distance Field shows the field. Scripts (pvpython, the
 * Python shell) keep their own control of time and colour.
 */
#ifndef pqShrinkWrapStarter_h
#define pqShrinkWrapStarter_h

#include <QObject>
#include <QPointer>

class pqPipelineSource;

class pqShrinkWrapStarter : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqShrinkWrapStarter(QObject* parent = nullptr);
  ~pqShrinkWrapStarter() override = default;

  void onStartup();
  void onShutdown() {}

private Q_SLOTS:
  void created(pqPipelineSource* source);
  void updated(pqPipelineSource* source);

private:
  Q_DISABLE_COPY(pqShrinkWrapStarter)
};

#endif
