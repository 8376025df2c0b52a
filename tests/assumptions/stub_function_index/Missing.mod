MODULE Missing
  ! Declarations written by 'rapidmc stubs' for the names the program uses and no module declares.
  ! Types come from the uses; values are neutral: replace them with the cell's real data.

  ! OpenGripper: first use prog.mod:10:9 (called)
  PROC OpenGripper()
  ENDPROC

  ! GetSlot: first use prog.mod:9:25 (array index)
  FUNC num GetSlot()
    RETURN 0;
  ENDFUNC
ENDMODULE
