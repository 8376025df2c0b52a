MODULE MainModule
  ! Tests: PoseMult(P1, P2) composes frames: trans = t1 + R1*t2, rot = q1*q2
  ! (P1 turned 180 degrees about z flips the x and y of t2).
  PROC main()
    VAR pose p1 := [[100, 0, 0], [0, 0, 0, 1]];
    VAR pose p2 := [[10, 20, 30], [1, 0, 0, 0]];
    VAR pose r;
    r := PoseMult(p1, p2);
    TPWrite "trans=" \Pos:=r.trans;
    TPWrite "rot=q1*q2=" \Bool:=r.rot = p1.rot;
    r := PoseMult(p2, p1);
    TPWrite "swapped=" \Pos:=r.trans;
  ENDPROC
ENDMODULE
