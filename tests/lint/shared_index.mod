MODULE SharedIndex
  PERS num slot := 1;
  PERS num count := 1;
  PERS num mode := 1;
  PERS num channel := 1;
  PERS num cursor := 1;
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
    Counted;
    Moded;
    Channels;
  ENDPROC

  PROC Next()
    IF slot < 1 OR slot > Dim(places, 1) RETURN;
    places{slot} := CRobT();
    Incr slot;
  ENDPROC

  ! A count without a bound: each use is the same finding, reported once with its places.
  PROC Counted()
    MoveL places{count}, v100, fine, gripper;  ! expect: RMC809
    MoveJ places{count}, v100, fine, gripper;  ! expect: RMC809
    count := count + 1;
  ENDPROC

  ! Only ever set to constants: a wrong value is not plausible, no finding (nor for a PERS
  ! no loaded code writes: a configuration value).
  PROC Moded()
    MoveL places{mode}, v100, fine, gripper;
    mode := 2;
    MoveL places{mode}, v100, fine, gripper;
    mode := -1;
  ENDPROC

  ! Passed by value: the routine cannot change it, no finding. Passed to an INOUT
  ! parameter: the routine may change it to anything.
  PROC Channels()
    Report channel;
    MoveL places{channel}, v100, fine, gripper;
    Advance cursor;
    MoveL places{cursor}, v100, fine, gripper;  ! expect: RMC809
  ENDPROC

  PROC Report(num number)
    TPWrite "channel " \Num:=number;
  ENDPROC

  PROC Advance(INOUT num position)
    position := position + 1;
  ENDPROC
ENDMODULE
