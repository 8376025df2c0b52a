MODULE MainModule
  ! Tests: an error-report interrupt (IError) is ordered and its trap reads the report with
  ! GetTrapData and ReadErrData; the event log is not modelled, so the trap never runs and
  ! the program goes on.
  VAR intnum irErrors;
  VAR trapdata tdError;
  VAR errdomain edDomain;
  VAR num nErrorId;
  VAR errtype etType;
  PROC main()
    CONNECT irErrors WITH trErrors;
    IError COMMON_ERR, TYPE_ALL, irErrors;
    TPWrite "supervising errors";
    IDelete irErrors;
  ENDPROC
  TRAP trErrors
    GetTrapData tdError;
    ReadErrData tdError, edDomain, nErrorId, etType \Title:=sTitle;
    TPWrite "error " \Num:=nErrorId;
  ENDTRAP
  VAR string sTitle;
ENDMODULE
