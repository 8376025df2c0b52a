MODULE isignaldo_trap_runs
  ! Tests: CONNECT binds an intnum to a TRAP; ISignalDO orders an interrupt
  ! on the rising edge (TriggValue 1) of an output; SetDO causing that edge
  ! runs the trap at the next instruction boundary, then execution resumes.
  VAR signaldo do1;
  VAR intnum irDo;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT irDo WITH onDo;
    ISignalDO do1, 1, irDo;
    TPWrite "before";
    SetDO do1, 1;
    TPWrite "after";
  ENDPROC
  TRAP onDo
    TPWrite "trap";
  ENDTRAP
ENDMODULE
