MODULE prog
  ! a cell's PLC writes the command and the step numbers (no loaded code writes them)
  PERS string command := "";
  PERS num running_step{2} := [4, 4];
  VAR num speeds{4} := [10, 20, 30, 40];
  VAR num speed;

  PROC main()
    WHILE TRUE DO
      IF running_step{1} <> 0 AND command = "Weld" speed := speeds{running_step{1}};
      WaitTime 0.1;
    ENDWHILE
  ENDPROC
ENDMODULE
