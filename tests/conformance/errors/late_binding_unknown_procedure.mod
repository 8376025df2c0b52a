MODULE late_binding_unknown_procedure
  ! Tests: a late-bound call naming no existing procedure raises
  ! ERR_REFUNKPRC, which an ERROR handler can catch.
  PROC main()
    VAR string name := "noSuchProc";
    %name%;
    TPWrite "after";
  ERROR
    IF ERRNO = ERR_REFUNKPRC TPWrite "unknown procedure";
    TRYNEXT;
  ENDPROC
ENDMODULE
