MODULE StatePublisher
    ! A state message whose record types are declared in a common module that was not
    ! given: components of components, one of them a joint position with its axes.
    LOCAL VAR state_msgs outgoing;

    PROC main()
        VAR num sent := 0;
        WHILE sent < 2 DO
            outgoing.header.sequence := sent;
            outgoing.feedback.angles.robax.rax_1 := 10 * sent;
            outgoing.feedback.angles.extax.eax_a := 9E9;
            outgoing.gripper.width := ReadGripperWidth();
            Incr sent;
        ENDWHILE
        TPWrite "sent "\Num:=outgoing.header.sequence;
    ENDPROC
ENDMODULE
