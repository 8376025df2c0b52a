MODULE OutsideArrayElementsKept
    ! Issue 28: a PC writes the approach targets; no RAPID code writes or compares them.
    ! Each element keeps its own value: the first turns about z, the second is the identity,
    ! and neither is the zero quaternion that mixing their components (q1 of the first,
    ! q4 of the second) would give.
    PERS robtarget pApproach{2} := [[[100, 0, 500], [0, 0, 0, 1], [0, 0, 0, 0],
        [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], [[200, 0, 500], [1, 0, 0, 0], [0, 0, 0, 0],
        [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]];
    VAR num nAngle := 0;

    PROC main()
        FOR i FROM 1 TO 2 DO
            nAngle := EulerZYX(\Z, pApproach{i}.rot);
        ENDFOR
    ENDPROC
ENDMODULE
