# pvbatch render_roller.py RESULT.exo OUT.png: the roller at the end of the slide, coloured by the
# von Mises stress, deformed by its displacement (the reader applies it), from the view of the symmetry
# plane z = 10 (docs/user-guide.md, "Worked example: from a CAD geometry to a result in ParaView").
# Run: xvfb-run -a pvbatch tests/regression/elements/render_roller.py roller_on_axle.exo roller_on_axle.png
import sys
from paraview.simple import *
reader = ExodusIIReader(FileName=[sys.argv[1]])
reader.ElementBlocks = ['roller']
reader.PointVariables = ['displ_']  # applied to the coordinates (Apply Displacements, on by default)
reader.ElementVariables = ['von_mises']
reader.UpdatePipelineInformation()
times = reader.TimestepValues
view = CreateRenderView()
view.ViewSize = [1000, 700]
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = times[-1]
view.ViewTime = times[-1]
reader.UpdatePipeline(times[-1])
display = Show(reader, view)
field = 'von_mises'
ColorBy(display, ('CELLS', field))
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction(field), view)
bar.Title = "von Mises stress (MPa)"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
display.RescaleTransferFunctionToDataRange(False, True)
view.CameraPosition = [25, 30, 45]
view.CameraFocalPoint = [0, 0, 5]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
SaveScreenshot(sys.argv[2], view, ImageResolution=[1000, 700])
print('field', field, 'times', len(times))
