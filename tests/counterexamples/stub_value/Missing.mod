MODULE Missing
  ! Declarations written by 'rapidmc stubs' for the names the program uses and no module declares.
  ! Types come from the uses; values are neutral: replace them with the cell's real data.

  ! gripper_mass: first use prog.mod:7:24 (assigned to num data)
  PERS num gripper_mass := 0;
ENDMODULE
