MODULE Static
  ! A controller reading the check fixes (GetMotorTorque, MaxRobSpeed) reads nothing another
  ! task writes: storing it in the task's own data is local, as the gantry's torque poll.
  PERS num nTorques{4} := [0, 0, 1, 0];
  PERS num speed := 100;
  PROC main()
    FOR i FROM 1 TO 2 DO
      nTorques{i} := Abs(GetMotorTorque(\mecunit:=ROB_1, i));  ! LOCAL
    ENDFOR
    nTorques{4} := MaxRobSpeed();                  ! LOCAL
    nTorques{3} := GetMotorTorque(1) + speed;      ! SHARED
    speed := MaxRobSpeed();                        ! SHARED
  ENDPROC
ENDMODULE
