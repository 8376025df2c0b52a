MODULE Gantry
    ! Written for the test (issue 28, PlanB's TASK7): the weld targets are declared here
    ! without a value; the planning task declares them with one and writes them. One
    ! persistent of several tasks is one object, so checked alone this task starts with the
    ! planner's value, as the controller does: its rotations are rotations.
    PERS robtarget pWelds{2};
    VAR num nAngle := 0;

    PROC main()
        nAngle := EulerZYX(\Z, pWelds{1}.rot);
        nAngle := EulerZYX(\Z, pWelds{2}.rot);
    ENDPROC
ENDMODULE
