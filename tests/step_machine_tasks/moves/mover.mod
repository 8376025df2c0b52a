! Task 1: moves where the check leaves the robot's position out (nothing reads it): the
! machine evaluates the arguments and goes on.  An element of a global array by a
! computed index (out of range while the other task's phase is 2: ERR_OUTOFBND, the
! machine's check fails and Python raises), a constant target with a work object, and a
! target computed by a function call (Python's).
MODULE Mover
  CONST robtarget home := [[500,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget points{3} := [[[400,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
                              [[450,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
                              [[500,50,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];
  VAR num n := 0;
  PERS num phase := 0;
  PROC main()
    WHILE TRUE DO
      n := n MOD 3 + 1;
      MoveJ points{n}, v100, fine, tool0;
      MoveL home, v100, z10, tool0 \WObj:=wobj0;
      IF phase = 2 MoveJ points{n + phase}, v100, fine, tool0;
      MoveJ Offs(home, 0, 0, n), v100, fine, tool0;
    ENDWHILE
  ENDPROC
ENDMODULE
