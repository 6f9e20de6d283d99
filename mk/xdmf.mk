# The XDMF sidecar read by a real reader: VTK's vtkXdmfReader, which ParaView
# opens .xmf files with (PyPI vtk, about 100 MB, so not part of make test,
# which checks the same sidecars as XML resolved with h5py).
#   make check-xdmf

.PHONY: check-xdmf

check-xdmf: build
	@python3 -c 'import vtkmodules.vtkIOXdmf2' 2>/dev/null || { echo "check-xdmf: installing vtk from PyPI"; \
		python3 -m pip install -q vtk 2>/dev/null || python3 -m pip install -q --break-system-packages vtk; }
	test/test_xdmf.sh bin/xcable
