MODULE MainModule
  ! Tests: WaitDO with \MaxTime and \TimeFlag sets the flag on timeout and continues.
  VAR signaldo doReady;
  PROC main()
    VAR bool late;
    AliasIO "DO1", doReady;
    WaitDO doReady, 1 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out=" \Bool:=late;
  ENDPROC
ENDMODULE
