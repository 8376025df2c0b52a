MODULE MainModule
  ! Tests: PulseDO sets the output high for the pulse length (\PLength, seconds) and then low
  ! again; program execution continues during the pulse.
  VAR signaldo doPulse;
  PROC main()
    AliasIO "DO1", doPulse;
    PulseDO \PLength:=1, doPulse;
    TPWrite "during=" \Num:=DOutput(doPulse);
    WaitTime 2;
    TPWrite "after=" \Num:=DOutput(doPulse);
  ENDPROC
ENDMODULE
