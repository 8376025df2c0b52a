MODULE SharedIndex
  PERS num slot := 1;
  VAR num local_slot := 1;
  VAR robtarget places{4};
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];

  PROC main()
    MoveL places{slot}, v100, fine, gripper;  ! expect: RMC809
    MoveL places{local_slot}, v100, fine, gripper;
    IF slot >= 1 AND slot <= 4 THEN
      MoveL places{slot}, v100, fine, gripper;
    ENDIF
    TEST slot
      CASE 1, 2:
        MoveL places{slot}, v100, fine, gripper;
    ENDTEST
    Next;
  ENDPROC

  PROC Next()
    IF slot < 1 OR slot > Dim(places, 1) RETURN;
    places{slot} := CRobT();
  ENDPROC
ENDMODULE
