MODULE Missing
  ! Declarations written by 'rapidmc stubs' for the names the program uses and no module declares.
  ! Types come from the uses; values are neutral: replace them with the cell's real data.

  ! newTargetFlag: first use prog.mod:10:16 (compared with bool)
  PERS bool newTargetFlag := FALSE;

  ! smIndx: first use prog.mod:12:20 (compared with string)
  PERS string smIndx := "";

  ! stateChoice: first use prog.mod:12:36 (Run argument state)
  PERS num stateChoice := 0;
ENDMODULE
