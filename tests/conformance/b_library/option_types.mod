MODULE MainModule
  ! Tests: data types of RobotWare options as controller backups declare them: arc welding
  ! (seamdata, welddata, weavedata), the sensor interface, list items, message headers.
  TASK PERS seamdata seam1 := [0.5,0.5,[5,0,24,120,0,0,0,0,0],0.5,1,10,0,5,[5,0,24,120,0,0,0,0,0],0,1,[5,0,24,120,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0];
  TASK PERS welddata weld1 := [6,0,[5,0,24,120,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  TASK PERS weavedata weave1 := [1,0,3,4,0,0,0,0,0,0,0,0,0,0,0];
  PERS sensor AnyDevice := [-1,-1,0];
  CONST listitem liMenu{2} := [["", "Start"], ["", "Stop"]];
  VAR rmqheader rhLast;
  VAR trapdata tdLast;
  PROC main()
    TPWrite "weld speed " \Num:=weld1.weld_speed;
    TPWrite "voltage " \Num:=weld1.main_arc.voltage;
    TPWrite "preflow " \Num:=seam1.preflow_time;
    TPWrite "weave width " \Num:=weave1.weave_width;
    TPWrite "sensor " \Num:=AnyDevice.id;
    TPWrite liMenu{2}.text;
    TPWrite "dims " \Num:=rhLast.ndim;
  ENDPROC
ENDMODULE
