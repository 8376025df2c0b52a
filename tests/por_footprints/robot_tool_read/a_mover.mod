MODULE Mover
  ! A move and a robot reading only read the PERS tool and work object they are passed:
  ! a move with a tool another task only reads with is its task's own; one with a tool
  ! another task writes is not (two motion tasks: one robot each).
  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tGun := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS tooldata tGrip := [TRUE,[[0,0,50],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PROC main()
    MoveL pHome, v100, fine, tGun \WObj:=wTable; ! LOCAL
    MoveJ pHome, v100, fine, tGrip;      ! SHARED
  ENDPROC
ENDMODULE
