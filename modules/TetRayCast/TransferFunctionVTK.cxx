// TransferFunction to and from a vtkVolumeProperty: the union of the colour and scalar-opacity
// functions' nodes, refined where VTK's functions are not linear between them.
#include "TransferFunction.h"

#include "Error.h"

#include <vtkColorTransferFunction.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace art
{
TransferFunction TransferFunction::FromVTK(vtkVolumeProperty* p)
{
  if (!p)
  {
    throw Error("no volume property");
  }
  // One colour channel (SetColor with a vtkPiecewiseFunction) is grey, as VTK's mappers draw it.
  // GetRGBTransferFunction would put VTK's default black-to-white ramp over 0..1024 in its place
  // (a grey of 0.8 on values near 1 drew black) and switch the user's property to three channels,
  // so VTK's own mappers lost the grey function too.
  vtkPiecewiseFunction* gtf = p->GetColorChannels(0) == 1 ? p->GetGrayTransferFunction(0) : nullptr;
  vtkColorTransferFunction* ctf = gtf ? nullptr : p->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = p->GetScalarOpacity(0);
  std::vector<double> s;
  double v[6];
  for (int i = 0; ctf && i < ctf->GetSize(); ++i)
  {
    ctf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  for (int i = 0; gtf && i < gtf->GetSize(); ++i)
  {
    gtf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  for (int i = 0; otf && i < otf->GetSize(); ++i)
  {
    otf->GetNodeValue(i, v);
    s.push_back(v[0]);
  }
  if (s.empty())
  {
    throw Error("volume property has neither colour nor opacity control points");
  }
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  // A function emptied of its points (RemoveAllPoints) is 0 everywhere, as VTK evaluates it and
  // VTK's mappers draw it: an emptied opacity function hides the volume (it drew it opaque), an
  // emptied colour function draws black (it drew white).
  auto at = [&](double x) {
    Node n{ x, { 1, 1, 1 }, 1.0, 0.0 };
    if (ctf)
    {
      if (ctf->GetSize() > 0)
      {
        ctf->GetColor(x, n.rgb);
      }
      else
      {
        n.rgb[0] = n.rgb[1] = n.rgb[2] = 0.0;
      }
    }
    if (gtf)
    {
      n.rgb[0] = n.rgb[1] = n.rgb[2] = gtf->GetSize() > 0 ? gtf->GetValue(x) : 0.0;
    }
    if (otf)
    {
      n.alpha = otf->GetSize() > 0 ? otf->GetValue(x) : 0.0;
    }
    return n;
  };
  // Between nodes VTK's functions are linear only in RGB with midpoint 0.5 and sharpness 0; other
  // colour spaces (Diverging, Lab, HSV: ParaView's defaults), midpoints, sharpness and a log
  // scale bend them. Such intervals are halved, up to 256 pieces, until the linear pieces are
  // within 1/500 of VTK's values at their quarter points.
  std::vector<Node> nodes;
  std::function<void(const Node&, const Node&, int)> refine = [&](const Node& a, const Node& b, int depth) {
    bool bent = false;
    Node q[3];
    for (int k = 0; k < 3; ++k)
    {
      const double f = 0.25 * (k + 1);
      q[k] = at(a.s + f * (b.s - a.s));
      for (int c = 0; c < 3 && !bent; ++c)
      {
        bent = std::fabs(q[k].rgb[c] - (a.rgb[c] + f * (b.rgb[c] - a.rgb[c]))) > 2e-3;
      }
      bent = bent || std::fabs(q[k].alpha - (a.alpha + f * (b.alpha - a.alpha))) > 2e-3;
    }
    if (!bent || depth >= 8)
    {
      return;
    }
    refine(a, q[1], depth + 1); // q[1]: the midpoint, already evaluated
    nodes.push_back(q[1]);
    refine(q[1], b, depth + 1);
  };
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const Node n = at(s[i]);
    if (i > 0)
    {
      const Node prev = nodes.back(); // a copy: refine appends to nodes
      refine(prev, n, 0);
    }
    nodes.push_back(n);
  }
  return TransferFunction(std::move(nodes), p->GetScalarOpacityUnitDistance(0));
}

void TransferFunction::ToVTK(vtkVolumeProperty* p) const
{
  vtkNew<vtkColorTransferFunction> ctf;
  vtkNew<vtkPiecewiseFunction> otf;
  for (const Node& n : N)
  {
    ctf->AddRGBPoint(n.s, n.rgb[0], n.rgb[1], n.rgb[2]);
    otf->AddPoint(n.s, n.alpha);
  }
  p->SetColor(0, ctf);
  p->SetScalarOpacity(0, otf);
  p->SetScalarOpacityUnitDistance(0, Unit);
  p->SetInterpolationTypeToLinear();
}
} // namespace art
