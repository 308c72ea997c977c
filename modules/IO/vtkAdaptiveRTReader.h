/**
 * @class vtkAdaptiveRTReader
 * @brief Reads every volume, mesh and surface format adaptivert reads, with its checks.
 *
 * One reader for C++ and Python pipelines: the file is read by art::Load (DataLoader.h), so the
 * output is what `adaptivert` would draw from it: a vtkImageData placed in the chosen frame
 * (patient: LPS patient coordinates; vtk: as VTK's own readers and ParaView place it), a
 * vtkUnstructuredGrid or a vtkPolyData, its field data holding "IndexToWorld" and "Frame". A
 * file that cannot be read whole (missing, cut short, a header that lies, a FIFO) is no crash
 * and no silently wrong data: Update reports a VTK error, GetErrorMessage() gives the one-line
 * reason ("<file>: <what is wrong>"), and the output is empty.
 */
#ifndef vtkAdaptiveRTReader_h
#define vtkAdaptiveRTReader_h

#include "AdaptiveRTIOModule.h"
#include "vtkAlgorithm.h"
#include "vtkSmartPointer.h" // for the data read

#include <string>

class ADAPTIVERTIO_EXPORT vtkAdaptiveRTReader : public vtkAlgorithm
{
public:
  static vtkAdaptiveRTReader* New();
  vtkTypeMacro(vtkAdaptiveRTReader, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The file, folder (DICOM, image slices) or slice pattern ("s%03d.png") to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /** A volume's point array to take as its scalars (NAME:magnitude, NAME:N too); empty: the default. */
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);

  /** Frame of a volume: "patient" (default) or "vtk". */
  vtkSetStringMacro(Frame);
  vtkGetStringMacro(Frame);

  /** A raw volume's layout (as ParaView's raw reader): sizes (0: not raw), type, spacing (also
   * the spacing of a stack of image slices, whose files hold none). */
  vtkSetVector3Macro(RawDimensions, int);
  vtkGetVector3Macro(RawDimensions, int);
  vtkSetStringMacro(RawScalarType);
  vtkGetStringMacro(RawScalarType);
  vtkSetVector3Macro(RawSpacing, double);
  vtkGetVector3Macro(RawSpacing, double);
  /** Bytes before the raw voxels; -1 (default): the voxels are the file's last bytes. */
  vtkSetMacro(RawHeaderSize, vtkTypeInt64);
  vtkGetMacro(RawHeaderSize, vtkTypeInt64);
  vtkSetMacro(RawBigEndian, bool);
  vtkGetMacro(RawBigEndian, bool);
  vtkBooleanMacro(RawBigEndian, bool);
  vtkSetClampMacro(RawComponents, int, 1, 1024);
  vtkGetMacro(RawComponents, int);

  /** Why the last Update produced no output ("" after a good read). */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /** The output: vtkImageData, vtkUnstructuredGrid or vtkPolyData (empty after an error). */
  vtkDataObject* GetOutput() { return this->GetOutputDataObject(0); }

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

protected:
  vtkAdaptiveRTReader();
  ~vtkAdaptiveRTReader() override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

private:
  vtkAdaptiveRTReader(const vtkAdaptiveRTReader&) = delete;
  void operator=(const vtkAdaptiveRTReader&) = delete;
  int RequestDataObject(vtkInformationVector* outInfo);
  int RequestInformation(vtkInformationVector* outInfo);
  int RequestData(vtkInformationVector* outInfo);
  bool ReadFile();

  char* FileName = nullptr;
  char* ArrayName = nullptr;
  char* Frame = nullptr;
  int RawDimensions[3] = { 0, 0, 0 };
  char* RawScalarType = nullptr;
  double RawSpacing[3] = { 1, 1, 1 };
  vtkTypeInt64 RawHeaderSize = -1;
  bool RawBigEndian = false;
  int RawComponents = 1;
  std::string ErrorMessage;
  vtkSmartPointer<vtkDataObject> Data; // read in RequestDataObject, handed out in RequestData
  vtkMTimeType ReadTime = 0;
};

#endif
