MODULE prog
  ! a PLC writes these PERS; the error is an index no check guards
  PERS num part_code := 1;
  PERS num conveyor_speed := 100;
  PERS num gripper_force := 20;
  PERS num lamp_mode := 0;
  PERS num shift_count := 0;
  VAR num bins{3} := [0, 0, 0];
  VAR robtarget left_arm;
  VAR robtarget right_arm;
  VAR num total;

  PROC main()
    left_arm := CRobT(\TaskName:="T_ROB_L");
    right_arm := CRobT(\TaskName:="T_ROB_R");
    total := conveyor_speed + gripper_force + lamp_mode + shift_count;
    IF part_code = 3 TPWrite "reject";
    bins{part_code} := 1;
  ENDPROC
ENDMODULE
