MODULE Planner
    ! Written for the test (issue 28): the planner declares the weld targets with the
    ! value the backup saved, and recomputes them.
    PERS robtarget pWelds{2} := [[[100, 0, 500], [0.707107, 0, 0, -0.707107], [0, 0, 0, 0],
        [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], [[200, 0, 500], [1, 0, 0, 0], [0, 0, 0, 0],
        [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]];

    PROC main()
        pWelds{2}.trans.x := pWelds{1}.trans.x + 100;
    ENDPROC
ENDMODULE
