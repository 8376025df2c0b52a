MODULE MainModule
  ! Tests: SetAO writes a (non-integer) value to an analog output; AOutput reads it back.
  VAR signalao aoSpeed;
  PROC main()
    AliasIO "AO1", aoSpeed;
    SetAO aoSpeed, 5.5;
    TPWrite "ao=" \Num:=AOutput(aoSpeed);
    SetAO aoSpeed, 0;
    TPWrite "ao=" \Num:=AOutput(aoSpeed);
  ENDPROC
ENDMODULE
