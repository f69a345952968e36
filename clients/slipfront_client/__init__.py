"""slipfront-client: a command-line and Python client of the slipfront simulation service
(submit and follow jobs, download verified results, studies) and the paper's figures from
result files. Needs only Debian's python3-requests, -h5py, -numpy and -matplotlib."""

__version__ = "0.1.0"
