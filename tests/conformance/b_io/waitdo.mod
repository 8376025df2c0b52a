MODULE MainModule
  ! Tests: WaitDO continues when the digital output has the awaited value.
  VAR signaldo doReady;
  PROC main()
    AliasIO "DO1", doReady;
    WaitDO doReady, 0;
    TPWrite "low seen";
    Set doReady;
    WaitDO doReady, 1;
    TPWrite "high seen";
  ENDPROC
ENDMODULE
