MODULE ReturnedCall
    ! A call the run came back from is told in one line when nothing the error reads was
    ! written inside it, its checks of inputs included (GoHome).  A FUNC
    ! whose value the failing path reads (Picked) stays shown, inputs and all.
    VAR num slots{3} := [1, 2, 3];
    VAR num homeSteps := 0;
    VAR num slot := 1;

    FUNC bool Picked()
        RETURN DInput(diPicked) = 1;
    ENDFUNC

    PROC GoHome()
        VAR robtarget here;
        here := CRobT();
        IF DInput(diAtHome) = 1 THEN
            homeSteps := 0;
        ELSEIF DInput(diNearHome) = 1 THEN
            homeSteps := homeSteps + 1;
        ELSE
            homeSteps := homeSteps + 2;
        ENDIF
    ENDPROC

    PROC main()
        GoHome;
        IF Picked() THEN
            slot := GInput(giSlot);
            slots{slot} := 0;
        ENDIF
    ENDPROC
ENDMODULE
